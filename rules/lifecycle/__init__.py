"""LV503-LV505: lifecycle bring-up (deadlocks, invalid transitions, lifecycle managers)."""
