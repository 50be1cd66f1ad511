"""Protocols composing runs and analysis (settle, noise, sweeps). Only the CLI and scenarios import this."""
