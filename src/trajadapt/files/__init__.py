"""Input and output: ROS recordings and their limits, plots, atomic files, the SQLite log."""
