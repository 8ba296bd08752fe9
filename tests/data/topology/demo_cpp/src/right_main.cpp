// The right driver's executable: it builds only the RightDriver of the shared library.
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<demo_cpp::RightDriver>());
  rclcpp::shutdown();
  return 0;
}
