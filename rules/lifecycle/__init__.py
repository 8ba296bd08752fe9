"""LV503-LV507: bring-up (lifecycle deadlocks and transitions, lifecycle managers, controllers)."""
