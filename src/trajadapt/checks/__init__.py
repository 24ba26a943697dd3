"""Checks and limits on a result: review notes, constraints, robot limits, projection, the measured effect."""
