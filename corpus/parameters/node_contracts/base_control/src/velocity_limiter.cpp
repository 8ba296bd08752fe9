#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "velocity_limiter_parameters.hpp"

class VelocityLimiter : public rclcpp::Node
{
public:
  VelocityLimiter()
  : Node("velocity_limiter"),
    listener_(std::make_shared<velocity_limiter::ParamListener>(this->get_node_parameters_interface()))
  {
    params_ = listener_->get_params();
  }

private:
  std::shared_ptr<velocity_limiter::ParamListener> listener_;
  velocity_limiter::Params params_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<VelocityLimiter>());
  rclcpp::shutdown();
  return 0;
}
