"""The conversation with the model: the answer format and its grammar, worked examples, the model file."""
