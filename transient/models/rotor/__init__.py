"""Rotors on bearings."""
