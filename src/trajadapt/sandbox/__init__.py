"""Run generated code isolated from the host: static check, restricted namespace, child process."""
