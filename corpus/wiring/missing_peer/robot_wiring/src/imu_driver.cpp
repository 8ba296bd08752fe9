// An IMU driver: publishes on imu/data, as REP 145 names it.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"

class ImuDriver : public rclcpp::Node
{
public:
  ImuDriver()
  : Node("imu_driver")
  {
    imu_pub_ = create_publisher<sensor_msgs::msg::Imu>("imu/data", 10);
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr imu_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ImuDriver>());
  rclcpp::shutdown();
  return 0;
}
