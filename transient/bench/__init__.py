"""Benchmarks behind ``transient bench ...``: each writes a markdown table (and plots) under docs/."""
