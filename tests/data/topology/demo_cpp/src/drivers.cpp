// A library of node classes shared by two executables: each main builds one of them.
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/string.hpp"

namespace demo_cpp
{

class DriverBase : public rclcpp::Node
{
public:
  explicit DriverBase(const std::string & name)
  : Node(name)
  {
    status_ = create_publisher<std_msgs::msg::String>("status", 1);  // expect: publisher status std_msgs/msg/String
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
};

class Watchdog
{
public:
  explicit Watchdog(rclcpp::Node * node)
  {
    pub_ = node->create_publisher<std_msgs::msg::Empty>("watchdog", 1);  // expect: publisher watchdog std_msgs/msg/Empty
  }

private:
  rclcpp::Publisher<std_msgs::msg::Empty>::SharedPtr pub_;
};

class LeftDriver : public DriverBase
{
public:
  LeftDriver()
  : DriverBase("left_driver"), watchdog_(this)
  {
    scan_ = create_publisher<sensor_msgs::msg::LaserScan>("left/scan", 5);  // expect: publisher left/scan sensor_msgs/msg/LaserScan
  }

private:
  Watchdog watchdog_;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_;
};

class RightDriver : public DriverBase
{
public:
  RightDriver()
  : DriverBase("right_driver")
  {
    scan_ = create_publisher<sensor_msgs::msg::LaserScan>("right/scan", 5);  // expect: publisher right/scan sensor_msgs/msg/LaserScan
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_;
};

}  // namespace demo_cpp
