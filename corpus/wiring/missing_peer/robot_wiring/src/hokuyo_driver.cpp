// A vendor driver that hard-codes the absolute name /scan.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

class HokuyoDriver : public rclcpp::Node
{
public:
  HokuyoDriver()
  : Node("hokuyo_driver")
  {
    scan_pub_ = create_publisher<sensor_msgs::msg::LaserScan>("/scan", 10);
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<HokuyoDriver>());
  rclcpp::shutdown();
  return 0;
}
