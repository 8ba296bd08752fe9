"""LV503-LV508: bring-up (lifecycle deadlocks, transitions and labels, managers, controllers)."""
