"""Python that does not parse as a whole: what the parser recovers is still read."""

from std_msgs.msg import Bool


def unfinished(:
    pass


class Half(Node):
    def __init__(self):
        super().__init__("half")  # expect-node-name: half
        self.ready = self.create_publisher(Bool, "ready", 1)  # expect: publisher ready std_msgs/msg/Bool
