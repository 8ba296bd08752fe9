// Says something on a relative topic, reports on a private one, broadcasts a frame.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "tf2_ros/transform_broadcaster.h"

class Talker : public rclcpp::Node
{
public:
  Talker()
  : Node("talker")
  {
    words_ = create_publisher<std_msgs::msg::String>("chatter", 10);
    status_ = create_publisher<std_msgs::msg::String>("~/status", 1);
    frames_ = std::make_unique<tf2_ros::TransformBroadcaster>(*this);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr words_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> frames_;
};

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>());
  rclcpp::shutdown();
  return 0;
}
