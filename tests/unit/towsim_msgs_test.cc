// msgs/: the generated types carry the ROS 2 DDS type names, and the IDL of towsim_msgs agrees
// field for field (and constant for constant) with the ROS 2 .msg files shipped beside it.

#include "towsim_msgs.h"

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "builtin_interfaces.h"
#include "geometry_msgs.h"
#include "nav_msgs.h"
#include "rosgraph_msgs.h"
#include "std_msgs.h"

namespace {

using Fields = std::vector<std::pair<std::string, std::string>>;  // (type, name)

std::string Read(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string StripComments(const std::string& text, const std::string& marker) {
  std::stringstream in(text), out;
  std::string line;
  while (std::getline(in, line)) {
    const auto c = line.find(marker);
    out << (c == std::string::npos ? line : line.substr(0, c)) << "\n";
  }
  return out.str();
}

// the members of `struct <name>_ { ... };` in the IDL, in order
Fields IdlMembers(const std::string& idl, const std::string& name) {
  const std::string text = StripComments(idl, "//");
  const std::regex head("struct\\s+" + name + "_\\s*\\{");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(text, m, head)) << name;
  const size_t begin = m.position(0) + m.length(0);
  const size_t end = text.find("};", begin);
  Fields fields;
  const std::regex member("\\s*(.+?)\\s+(\\w+(?:\\[\\d+\\])?)\\s*;\\s*");
  std::stringstream body(text.substr(begin, end - begin));
  std::string line;
  while (std::getline(body, line)) {
    if (std::regex_match(line, m, member)) fields.emplace_back(m[1], m[2]);
  }
  return fields;
}

// const uint8 NAME = value; in module <name>_Constants
std::map<std::string, std::string> IdlConstants(const std::string& idl, const std::string& name) {
  std::map<std::string, std::string> out;
  const std::string text = StripComments(idl, "//");
  const size_t begin = text.find("module " + name + "_Constants");
  if (begin == std::string::npos) return out;
  const size_t end = text.find("};", begin);
  const std::regex constant("const\\s+(\\w+)\\s+(\\w+)\\s*=\\s*(\\w+)\\s*;");
  const std::string block = text.substr(begin, end - begin);
  for (std::sregex_iterator i(block.begin(), block.end(), constant), e; i != e; ++i) {
    out[(*i)[2]] = (*i)[1].str() + " " + (*i)[3].str();
  }
  return out;
}

// ROS 2 .msg type -> the IDL rosidl_generator_dds_idl would write
std::string IdlType(const std::string& msg_type) {
  if (msg_type.size() > 2 && msg_type.compare(msg_type.size() - 2, 2, "[]") == 0) {
    return "sequence<" + IdlType(msg_type.substr(0, msg_type.size() - 2)) + ">";
  }
  static const std::map<std::string, std::string> kBase = {
      {"bool", "boolean"},         {"uint8", "uint8"},     {"int32", "long"},
      {"uint32", "unsigned long"}, {"int64", "long long"}, {"uint64", "unsigned long long"},
      {"float64", "double"},       {"string", "string"}};
  if (const auto it = kBase.find(msg_type); it != kBase.end()) return it->second;
  const auto slash = msg_type.find('/');
  if (slash == std::string::npos) return "?" + msg_type;
  return msg_type.substr(0, slash) + "::msg::dds_::" + msg_type.substr(slash + 1) + "_";
}

void MsgFile(const std::string& text, Fields* fields, std::map<std::string, std::string>* consts) {
  std::stringstream in(StripComments(text, "#"));
  std::string line;
  const std::regex constant("\\s*(\\w+)\\s+(\\w+)\\s*=\\s*(\\w+)\\s*");
  const std::regex field("\\s*(\\S+)\\s+(\\w+)\\s*");
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_match(line, m, constant)) {
      (*consts)[m[2]] = IdlType(m[1]) + " " + m[3].str();
    } else if (std::regex_match(line, m, field)) {
      fields->emplace_back(IdlType(m[1]), m[2]);
    }
  }
}

class TowsimMsgsTest : public ::testing::TestWithParam<const char*> {};

TEST_P(TowsimMsgsTest, IdlMatchesTheRos2MsgFile) {
  const std::string name = GetParam();
  const std::string idl = Read(TOWSIM_SOURCE_DIR "/msgs/idl/towsim_msgs.idl");
  Fields msg_fields;
  std::map<std::string, std::string> msg_consts;
  MsgFile(Read(std::string(TOWSIM_SOURCE_DIR) + "/msgs/towsim_msgs/msg/" + name + ".msg"),
          &msg_fields, &msg_consts);
  EXPECT_EQ(IdlMembers(idl, name), msg_fields);
  EXPECT_EQ(IdlConstants(idl, name), msg_consts);
  EXPECT_FALSE(msg_fields.empty());
}

INSTANTIATE_TEST_SUITE_P(AllMessages, TowsimMsgsTest,
                         ::testing::Values("CableState", "ActuatorCommand", "SimStatus",
                                           "SimControl", "SceneInfo", "WinchCommand"));

TEST(MsgTypeNamesTest, AreTheRos2DdsNames) {
  const std::map<std::string, const dds_topic_descriptor_t*> types = {
      {"builtin_interfaces::msg::dds_::Time_", &builtin_interfaces_msg_dds__Time__desc},
      {"std_msgs::msg::dds_::Header_", &std_msgs_msg_dds__Header__desc},
      {"geometry_msgs::msg::dds_::Point_", &geometry_msgs_msg_dds__Point__desc},
      {"geometry_msgs::msg::dds_::Vector3_", &geometry_msgs_msg_dds__Vector3__desc},
      {"geometry_msgs::msg::dds_::Quaternion_", &geometry_msgs_msg_dds__Quaternion__desc},
      {"geometry_msgs::msg::dds_::Pose_", &geometry_msgs_msg_dds__Pose__desc},
      {"geometry_msgs::msg::dds_::Twist_", &geometry_msgs_msg_dds__Twist__desc},
      {"geometry_msgs::msg::dds_::Wrench_", &geometry_msgs_msg_dds__Wrench__desc},
      {"geometry_msgs::msg::dds_::WrenchStamped_", &geometry_msgs_msg_dds__WrenchStamped__desc},
      {"geometry_msgs::msg::dds_::PoseWithCovariance_",
       &geometry_msgs_msg_dds__PoseWithCovariance__desc},
      {"geometry_msgs::msg::dds_::TwistWithCovariance_",
       &geometry_msgs_msg_dds__TwistWithCovariance__desc},
      {"nav_msgs::msg::dds_::Odometry_", &nav_msgs_msg_dds__Odometry__desc},
      {"rosgraph_msgs::msg::dds_::Clock_", &rosgraph_msgs_msg_dds__Clock__desc},
      {"towsim_msgs::msg::dds_::CableState_", &towsim_msgs_msg_dds__CableState__desc},
      {"towsim_msgs::msg::dds_::ActuatorCommand_", &towsim_msgs_msg_dds__ActuatorCommand__desc},
      {"towsim_msgs::msg::dds_::SimStatus_", &towsim_msgs_msg_dds__SimStatus__desc},
      {"towsim_msgs::msg::dds_::SimControl_", &towsim_msgs_msg_dds__SimControl__desc},
      {"towsim_msgs::msg::dds_::SceneInfo_", &towsim_msgs_msg_dds__SceneInfo__desc},
      {"towsim_msgs::msg::dds_::WinchCommand_", &towsim_msgs_msg_dds__WinchCommand__desc},
  };
  for (const auto& [name, desc] : types) {
    EXPECT_EQ(std::string(desc->m_typename), name);
    EXPECT_EQ(desc->m_nkeys, 0u) << name << ": keyless";
  }
}

TEST(MsgLayoutTest, StandardTypesHaveTheRos2Fields) {
  const std::string idl_dir = TOWSIM_SOURCE_DIR "/msgs/idl/";
  const Fields odometry = {{"std_msgs::msg::dds_::Header_", "header"},
                           {"string", "child_frame_id"},
                           {"geometry_msgs::msg::dds_::PoseWithCovariance_", "pose"},
                           {"geometry_msgs::msg::dds_::TwistWithCovariance_", "twist"}};
  EXPECT_EQ(IdlMembers(Read(idl_dir + "nav_msgs.idl"), "Odometry"), odometry);
  const std::string geometry = Read(idl_dir + "geometry_msgs.idl");
  EXPECT_EQ(IdlMembers(geometry, "PoseWithCovariance"),
            (Fields{{"Pose_", "pose"}, {"double", "covariance[36]"}}));
  EXPECT_EQ(IdlMembers(geometry, "Quaternion"),
            (Fields{{"double", "x"}, {"double", "y"}, {"double", "z"}, {"double", "w"}}));
  EXPECT_EQ(IdlMembers(Read(idl_dir + "std_msgs.idl"), "Header"),
            (Fields{{"builtin_interfaces::msg::dds_::Time_", "stamp"}, {"string", "frame_id"}}));
  EXPECT_EQ(IdlMembers(Read(idl_dir + "builtin_interfaces.idl"), "Time"),
            (Fields{{"long", "sec"}, {"unsigned long", "nanosec"}}));
  EXPECT_EQ(IdlMembers(Read(idl_dir + "rosgraph_msgs.idl"), "Clock"),
            (Fields{{"builtin_interfaces::msg::dds_::Time_", "clock"}}));
}

}  // namespace
