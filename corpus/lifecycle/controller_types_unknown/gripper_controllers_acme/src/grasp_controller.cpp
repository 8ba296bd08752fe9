#include "controller_interface/controller_interface.hpp"

namespace acme_gripper_controllers
{
class GraspController : public controller_interface::ControllerInterface
{
};
}  // namespace acme_gripper_controllers
