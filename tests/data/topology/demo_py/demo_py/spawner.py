"""A helper module the follower imports: its client belongs to the follower's executable."""

from turtlesim.srv import Spawn


class Spawner:
    def __init__(self, node):
        self.client = node.create_client(Spawn, "spawn")  # expect: client spawn turtlesim/srv/Spawn
