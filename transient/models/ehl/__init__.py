"""Pieces shared by the EHL contacts (the line, the roller and the point contact)."""
