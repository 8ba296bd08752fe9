"""Rules about conditions: never true, always true, values launch rejects."""
