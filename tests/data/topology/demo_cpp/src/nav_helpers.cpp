// A lifecycle server built the way nav2's servers are (jazzy's and kilted's idioms): helper
// classes of nav2_util, nav_2d_utils, nav2_costmap_2d and diagnostic_updater create its
// endpoints.
#include <memory>
#include <string>

using DriveAction = demo_msgs::action::Drive;
using DriveServer = nav2_util::SimpleActionServer<DriveAction>;

class Updater
{
public:
  explicit Updater(void * owner) {}
};

class HelperServer : public nav2_util::LifecycleNode
{
public:
  HelperServer()
  : nav2_util::LifecycleNode("helper_server"),  // expect-node-name: helper_server
    diagnostics_(this)  // expect: publisher /diagnostics diagnostic_msgs/msg/DiagnosticArray via=diagnostic_updater
  {
    nav2_util::declare_parameter_if_not_declared(this, "odom_topic", rclcpp::ParameterValue("odom"));
    add_parameter("map_topic", rclcpp::ParameterValue("map"), "the map to follow");
    costmap_ = std::make_shared<nav2_costmap_2d::Costmap2DROS>("local_map", std::string{get_namespace()}, "local_map", false);  // expect: publisher local_map/costmap nav_msgs/msg/OccupancyGrid via=nav2_costmap_2d ; publisher local_map/costmap_raw nav2_msgs/msg/Costmap via=nav2_costmap_2d ; publisher local_map/costmap_updates map_msgs/msg/OccupancyGridUpdate via=nav2_costmap_2d ; publisher local_map/costmap_raw_updates nav2_msgs/msg/CostmapUpdate via=nav2_costmap_2d ; publisher local_map/published_footprint geometry_msgs/msg/PolygonStamped via=nav2_costmap_2d ; subscription local_map/footprint geometry_msgs/msg/Polygon via=nav2_costmap_2d ; service local_map/get_costmap nav2_msgs/srv/GetCostmap via=nav2_costmap_2d ; service local_map/get_cost_local_map nav2_msgs/srv/GetCost via=nav2_costmap_2d ; service local_map/clear_except_local_map nav2_msgs/srv/ClearCostmapExceptRegion via=nav2_costmap_2d ; service local_map/clear_around_local_map nav2_msgs/srv/ClearCostmapAroundRobot via=nav2_costmap_2d ; service local_map/clear_around_pose_local_map nav2_msgs/srv/ClearCostmapAroundPose via=nav2_costmap_2d ; service local_map/clear_entirely_local_map nav2_msgs/srv/ClearEntireCostmap via=nav2_costmap_2d
    kilted_ = std::make_shared<nav2_costmap_2d::Costmap2DROS>("kilted_map", std::string{get_namespace()}, get_parameter("use_sim_time").as_bool(), options);  // expect: publisher kilted_map/costmap nav_msgs/msg/OccupancyGrid via=nav2_costmap_2d ; publisher kilted_map/costmap_raw nav2_msgs/msg/Costmap via=nav2_costmap_2d ; publisher kilted_map/costmap_updates map_msgs/msg/OccupancyGridUpdate via=nav2_costmap_2d ; publisher kilted_map/costmap_raw_updates nav2_msgs/msg/CostmapUpdate via=nav2_costmap_2d ; publisher kilted_map/published_footprint geometry_msgs/msg/PolygonStamped via=nav2_costmap_2d ; subscription kilted_map/footprint geometry_msgs/msg/Polygon via=nav2_costmap_2d ; service kilted_map/get_costmap nav2_msgs/srv/GetCostmap via=nav2_costmap_2d ; service kilted_map/get_cost_kilted_map nav2_msgs/srv/GetCost via=nav2_costmap_2d ; service kilted_map/clear_except_kilted_map nav2_msgs/srv/ClearCostmapExceptRegion via=nav2_costmap_2d ; service kilted_map/clear_around_kilted_map nav2_msgs/srv/ClearCostmapAroundRobot via=nav2_costmap_2d ; service kilted_map/clear_around_pose_kilted_map nav2_msgs/srv/ClearCostmapAroundPose via=nav2_costmap_2d ; service kilted_map/clear_entirely_kilted_map nav2_msgs/srv/ClearEntireCostmap via=nav2_costmap_2d
    standalone_ = std::make_shared<nav2_costmap_2d::Costmap2DROS>("elsewhere", false);  // expect: publisher /elsewhere/costmap nav_msgs/msg/OccupancyGrid via=nav2_costmap_2d ; publisher /elsewhere/costmap_raw nav2_msgs/msg/Costmap via=nav2_costmap_2d ; publisher /elsewhere/costmap_updates map_msgs/msg/OccupancyGridUpdate via=nav2_costmap_2d ; publisher /elsewhere/costmap_raw_updates nav2_msgs/msg/CostmapUpdate via=nav2_costmap_2d ; publisher /elsewhere/published_footprint geometry_msgs/msg/PolygonStamped via=nav2_costmap_2d ; subscription /elsewhere/footprint geometry_msgs/msg/Polygon via=nav2_costmap_2d ; service /elsewhere/get_costmap nav2_msgs/srv/GetCostmap via=nav2_costmap_2d ; service /elsewhere/get_cost_elsewhere nav2_msgs/srv/GetCost via=nav2_costmap_2d ; service /elsewhere/clear_except_elsewhere nav2_msgs/srv/ClearCostmapExceptRegion via=nav2_costmap_2d ; service /elsewhere/clear_around_elsewhere nav2_msgs/srv/ClearCostmapAroundRobot via=nav2_costmap_2d ; service /elsewhere/clear_around_pose_elsewhere nav2_msgs/srv/ClearCostmapAroundPose via=nav2_costmap_2d ; service /elsewhere/clear_entirely_elsewhere nav2_msgs/srv/ClearEntireCostmap via=nav2_costmap_2d
  }

  void configure()
  {
    auto node = shared_from_this();
    get_parameter("odom_topic", odom_topic_);
    get_parameter("map_topic", map_topic_);
    auto scan_topic = declare_or_get_parameter("scan_topic", std::string("scan"));
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(scan_topic, 1, on_scan);  // expect: subscription scan sensor_msgs/msg/LaserScan param=scan_topic
    map_sub_ = create_subscription<nav_msgs::msg::OccupancyGrid>(map_topic_, 1, on_map);  // expect: subscription map nav_msgs/msg/OccupancyGrid param=map_topic
    odom_ = std::make_unique<nav_2d_utils::OdomSubscriber>(node);  // expect: subscription odom nav_msgs/msg/Odometry param=odom_topic via=nav_2d_utils
    smoother_ = std::make_unique<nav2_util::OdomSmoother>(node, 0.3, odom_topic_);  // expect: subscription odom nav_msgs/msg/Odometry param=odom_topic via=nav2_util
    cmd_out_ = std::make_unique<nav2_util::TwistPublisher>(node, "cmd_vel", 1);  // expect: publisher cmd_vel ? via=nav2_util
    cmd_in_ = std::make_unique<nav2_util::TwistSubscriber>(node, "cmd_vel_in", 1, on_twist, on_stamped);  // expect: subscription cmd_vel_in ? via=nav2_util
    server_ = std::make_unique<DriveServer>(node, "drive", execute_callback);  // expect: action_server drive demo_msgs/action/Drive via=nav2_util
    client_ = std::make_shared<nav2_util::ServiceClient<std_srvs::srv::Trigger>>("/reset", node);  // expect: client /reset std_srvs/srv/Trigger via=nav2_util
    costmap_sub_ = std::make_unique<nav2_costmap_2d::CostmapSubscriber>(node, "global_map/costmap_raw");  // expect: subscription global_map/costmap_raw nav2_msgs/msg/Costmap via=nav2_costmap_2d ; subscription global_map/costmap_raw_updates nav2_msgs/msg/CostmapUpdate via=nav2_costmap_2d
    footprint_sub_ = std::make_unique<nav2_costmap_2d::FootprintSubscriber>(node, "global_map/published_footprint", *tf_, "base_link", 0.1);  // expect: subscription global_map/published_footprint geometry_msgs/msg/PolygonStamped via=nav2_costmap_2d
    manage_ = create_service<std_srvs::srv::Trigger>(get_name() + std::string("/manage"), on_manage);  // expect: service ~/manage std_srvs/srv/Trigger
    odd_ = create_service<std_srvs::srv::Trigger>(get_name() + std::string("_odd"), on_manage);  // expect: service ? std_srvs/srv/Trigger unresolved
    mine_ = std::make_unique<Updater>(this);
  }

  rcl_interfaces::msg::SetParametersResult on_parameters(std::vector<rclcpp::Parameter> parameters)
  {
    for (auto & parameter : parameters) {
      const auto & name = parameter.get_name();
      if (name == "odom_topic") {
        odom_topic_ = parameter.as_string();
      }
    }
    return {};
  }

private:
  diagnostic_updater::Updater diagnostics_;
  std::string odom_topic_;
};
