"""Closed forms and set-ups shared by the tests and the scenarios."""
