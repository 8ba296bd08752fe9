// Logs the odometry it receives.
#include <memory>

#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"

class OdomLogger : public rclcpp::Node
{
public:
  OdomLogger()
  : Node("odom_logger")
  {
    odom_sub_ = create_subscription<nav_msgs::msg::Odometry>(
      "odom", 10,
      [this](nav_msgs::msg::Odometry::ConstSharedPtr msg) {
        RCLCPP_INFO(get_logger(), "x=%f", msg->pose.pose.position.x);
      });
  }

private:
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<OdomLogger>());
  rclcpp::shutdown();
  return 0;
}
