"""Reading the answer against the user's words (see READERS for the run order)."""
