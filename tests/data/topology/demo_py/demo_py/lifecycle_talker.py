"""A managed node: its publisher exists from configure on, but the name is known here."""

from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from std_msgs.msg import String


class LifecycleTalker(LifecycleNode):
    def __init__(self, **kwargs):
        super().__init__("lc_talker", **kwargs)  # expect-node-name: lc_talker
        self.declare_parameter("topic", "lifecycle_chatter")
        self.publisher = None

    def on_configure(self, state):
        topic = self.get_parameter("topic").value
        self.publisher = self.create_lifecycle_publisher(String, topic, 10)  # expect: publisher lifecycle_chatter std_msgs/msg/String param=topic
        return TransitionCallbackReturn.SUCCESS
