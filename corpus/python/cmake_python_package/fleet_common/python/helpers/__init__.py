"""The fleet's naming helpers (installed as fleet_names)."""
