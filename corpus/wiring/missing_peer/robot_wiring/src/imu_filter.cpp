// A complementary filter whose author wrote imu_data for imu/data.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"

class ImuFilter : public rclcpp::Node
{
public:
  ImuFilter()
  : Node("imu_filter")
  {
    filtered_pub_ = create_publisher<sensor_msgs::msg::Imu>("imu/filtered", 10);
    imu_sub_ = create_subscription<sensor_msgs::msg::Imu>(
      "imu_data", 10,
      [this](sensor_msgs::msg::Imu::ConstSharedPtr msg) {filtered_pub_->publish(*msg);});
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr filtered_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ImuFilter>());
  rclcpp::shutdown();
  return 0;
}
