"""The papers' parameter sets as data (SI), one module per paper."""
