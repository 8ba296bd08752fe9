// The left driver's executable: it builds only the LeftDriver of the shared library.
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<demo_cpp::LeftDriver>());
  rclcpp::shutdown();
  return 0;
}
