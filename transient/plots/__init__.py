"""matplotlib figures drawn from Results only; every paper figure is drawable from the installed package."""
