"""What DDS sees of a launch: which domain and discovery range each node's process uses."""
