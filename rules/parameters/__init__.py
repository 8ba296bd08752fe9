"""Rules about parameters and parameter files."""
