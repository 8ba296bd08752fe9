#include "controller_interface/controller_interface.hpp"

namespace rover_controllers
{
class TractionController : public controller_interface::ControllerInterface
{
};
}  // namespace rover_controllers
