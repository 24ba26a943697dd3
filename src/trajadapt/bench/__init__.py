"""Benchmark: run many cases non-interactively and score whether each adaptation did what was asked."""
