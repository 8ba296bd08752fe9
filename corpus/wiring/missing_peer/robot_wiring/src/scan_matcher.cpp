// Laser odometry: scans in, odometry out, and a private service to reset the pose.
#include <memory>

#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_srvs/srv/trigger.hpp"

class ScanMatcher : public rclcpp::Node
{
public:
  ScanMatcher()
  : Node("scan_matcher")
  {
    odom_pub_ = create_publisher<nav_msgs::msg::Odometry>("odom", 10);
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::LaserScan::ConstSharedPtr) {odom_pub_->publish(nav_msgs::msg::Odometry());});
    reset_srv_ = create_service<std_srvs::srv::Trigger>(
      "~/reset",
      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {response->success = true;});
  }

private:
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr reset_srv_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ScanMatcher>());
  rclcpp::shutdown();
  return 0;
}
