// io/ros2_schemas: the ros2msg schema of every IDL type in msgs/ (complete, fields as the IDL),
// the dependency layout rosbag2 writes, DDS -> ROS 2 type names, the rosbag2 metadata record.
#include "io/ros2_schemas.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "io/mcap_reader.h"
#include "io/mcap_writer.h"
#include "temp_dir.h"

namespace towsim::io {
namespace {

using Field = std::pair<std::string, std::string>;  // (ros2 type, name)

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// an IDL type of msgs/idl as a ROS 2 .msg type in package `pkg`:
// "std_msgs::msg::dds_::Header_" -> "std_msgs/Header", "Point_" -> "geometry_msgs/Point"
std::string IdlToRos2(std::string t, const std::string& pkg) {
  static const std::map<std::string, std::string> kPrimitive = {
      {"long", "int32"},      {"unsigned long", "uint32"},
      {"long long", "int64"}, {"unsigned long long", "uint64"},
      {"double", "float64"},  {"float", "float32"},
      {"uint8", "uint8"},     {"octet", "byte"},
      {"boolean", "bool"},    {"string", "string"},
      {"short", "int16"},     {"unsigned short", "uint16"}};
  t = Trim(t);
  if (auto it = kPrimitive.find(t); it != kPrimitive.end()) return it->second;
  std::smatch m;
  if (std::regex_match(t, m, std::regex(R"(string<\s*(\d+)\s*>)"))) {
    return "string<=" + std::string(m[1]);  // a bounded string
  }
  if (std::regex_match(t, m, std::regex(R"(sequence<\s*(.+?)\s*>)"))) {
    return IdlToRos2(m[1], pkg) + "[]";
  }
  if (std::regex_match(t, m, std::regex(R"((\w+)::msg::dds_::(\w+)_)"))) {
    return std::string(m[1]) + "/" + std::string(m[2]);
  }
  if (std::regex_match(t, m, std::regex(R"((\w+)_)"))) return pkg + "/" + std::string(m[1]);
  ADD_FAILURE() << "IDL type not understood: '" << t << "'";
  return t;
}

// every struct of msgs/idl/*.idl: "pkg/Name" -> fields in order (ROS 2 types)
std::map<std::string, std::vector<Field>> ParseIdl() {
  std::map<std::string, std::vector<Field>> out;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(TOWSIM_SOURCE_DIR) / "msgs/idl")) {
    if (entry.path().extension() != ".idl") continue;
    const std::string pkg = entry.path().stem().string();
    std::string text = Slurp(entry.path());
    text = std::regex_replace(text, std::regex("//[^\n]*"), "");
    text = std::regex_replace(text, std::regex("#[^\n]*"), "");
    const std::regex kStruct(R"(struct\s+(\w+)_\s*\{([^}]*)\})");
    for (std::sregex_iterator it(text.begin(), text.end(), kStruct), end; it != end; ++it) {
      std::vector<Field> fields;
      const std::string body = (*it)[2];
      std::istringstream members(body);
      for (std::string member; std::getline(members, member, ';');) {
        member = Trim(member);
        if (member.empty()) continue;
        std::smatch m;
        // "<type> <name>" or "<type> <name>[N]"
        if (!std::regex_match(member, m, std::regex(R"(([\s\S]+?)\s+(\w+)(\[(\d+)\])?)"))) {
          ADD_FAILURE() << "IDL member not understood: " << member;
          continue;
        }
        std::string type = IdlToRos2(m[1], pkg);
        if (m[3].matched) type += "[" + std::string(m[4]) + "]";
        fields.emplace_back(type, m[2]);
      }
      out[pkg + "/" + std::string((*it)[1])] = fields;
    }
  }
  return out;
}

bool IsPrimitive(std::string type) {
  type = type.substr(0, type.find_first_of("[<"));  // arrays, bounded strings
  static const std::set<std::string> kPrimitive = {
      "bool",  "byte",   "char",  "float32", "float64", "int8",   "uint8",
      "int16", "uint16", "int32", "uint32",  "int64",   "uint64", "string"};
  return kPrimitive.count(type) > 0;
}

// a .msg block: its fields, with types made absolute ("Point" in geometry_msgs ->
// "geometry_msgs/Point"); constants ("uint8 PAUSE=1") and comments skipped
std::vector<Field> MsgFields(const std::string& text, const std::string& pkg) {
  std::vector<Field> fields;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    line = Trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string type, name;
    words >> type >> name;
    if (name.find('=') != std::string::npos) continue;  // a constant
    // ROS 2's char is uint8 (rosidl maps it to the IDL uint8)
    if (type.rfind("char", 0) == 0) type = "uint8" + type.substr(4);
    if (!IsPrimitive(type) && type.find('/') == std::string::npos) type = pkg + "/" + type;
    fields.emplace_back(type, name);
  }
  return fields;
}

struct Block {
  std::string name;  // "pkg/Name"; the root block: the schema's type
  std::string text;
};

// splits a ros2msg schema at its separator lines
std::vector<Block> SplitSchema(const std::string& schema, const std::string& root) {
  const std::string sep = std::string(80, '=') + "\n";
  std::vector<Block> blocks;
  std::size_t pos = 0;
  std::string name = root;
  for (;;) {
    const auto next = schema.find("\n" + sep, pos);
    const std::string text = schema.substr(pos, next == std::string::npos ? next : next - pos);
    blocks.push_back({name, text + "\n"});
    if (next == std::string::npos) break;
    const auto line_start = next + 1 + sep.size();
    const auto line_end = schema.find('\n', line_start);
    const std::string msg_line = schema.substr(line_start, line_end - line_start);
    EXPECT_EQ(msg_line.rfind("MSG: ", 0), 0u) << msg_line;
    name = msg_line.substr(5);
    pos = line_end + 1;
  }
  return blocks;
}

TEST(Ros2Schemas, EveryIdlTypeHasACompleteSchemaWithTheIdlFields) {
  const auto idl = ParseIdl();
  ASSERT_GE(idl.size(), 18u);  // 13 standard + 5 towsim_msgs structs
  for (const auto& [short_name, idl_fields] : idl) {
    SCOPED_TRACE(short_name);
    const std::string pkg = short_name.substr(0, short_name.find('/'));
    const std::string dds = pkg + "::msg::dds_::" + short_name.substr(pkg.size() + 1) + "_";
    const std::string ros2 = Ros2TypeName(dds);
    EXPECT_EQ(ros2, pkg + "/msg/" + short_name.substr(pkg.size() + 1));
    const std::string schema = Ros2MsgSchema(ros2);
    const auto blocks = SplitSchema(schema, short_name);
    std::set<std::string> names;
    for (const Block& b : blocks) EXPECT_TRUE(names.insert(b.name).second) << "twice: " << b.name;
    for (const Block& b : blocks) {
      SCOPED_TRACE(b.name);
      ASSERT_EQ(idl.count(b.name), 1u) << "a block of a type the IDL does not define";
      const auto fields = MsgFields(b.text, b.name.substr(0, b.name.find('/')));
      EXPECT_EQ(fields, idl.at(b.name));  // names, types and order as the IDL
      for (const auto& [type, name] : fields) {
        if (IsPrimitive(type)) continue;
        EXPECT_EQ(names.count(type.substr(0, type.find('['))), 1u)
            << "field " << name << " of type " << type << " has no MSG: block";
      }
    }
  }
}

TEST(Ros2Schemas, DependenciesDepthFirstSortedOnceEachAsRosbag2) {
  const std::string schema = Ros2MsgSchema("nav_msgs/msg/Odometry");
  std::vector<std::string> order;
  for (const Block& b : SplitSchema(schema, "nav_msgs/Odometry")) order.push_back(b.name);
  // Odometry's direct deps sorted: geometry_msgs/PoseWithCovariance, .../TwistWithCovariance,
  // std_msgs/Header; each expanded depth first before the next
  const std::vector<std::string> expected = {
      "nav_msgs/Odometry",        "geometry_msgs/PoseWithCovariance",
      "geometry_msgs/Pose",       "geometry_msgs/Point",
      "geometry_msgs/Quaternion", "geometry_msgs/TwistWithCovariance",
      "geometry_msgs/Twist",      "geometry_msgs/Vector3",
      "std_msgs/Header",          "builtin_interfaces/Time"};
  EXPECT_EQ(order, expected);
  // the exact text of a small one: the .msg, "\n", 80 '=', "MSG: pkg/Name", the dependency
  EXPECT_EQ(Ros2MsgSchema("rosgraph_msgs/msg/Clock"),
            "builtin_interfaces/Time clock\n\n" + std::string(80, '=') +
                "\nMSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n");
  EXPECT_EQ(Ros2MsgSchema("builtin_interfaces/msg/Time"), "int32 sec\nuint32 nanosec\n");
  // "pkg/Name" is accepted as well
  EXPECT_EQ(Ros2MsgSchema("nav_msgs/Odometry"), schema);
}

TEST(Ros2Schemas, TowsimMessagesAreTheMsgFilesVerbatim) {
  for (const char* name :
       {"ActuatorCommand", "CableState", "SceneInfo", "SimControl", "SimStatus", "WinchCommand"}) {
    const auto path = std::filesystem::path(TOWSIM_SOURCE_DIR) / "msgs/towsim_msgs/msg" /
                      (std::string(name) + ".msg");
    const std::string text = Slurp(path);
    const std::string schema = Ros2MsgSchema(std::string("towsim_msgs/msg/") + name);
    EXPECT_EQ(schema.substr(0, text.size()), text) << name;
    EXPECT_EQ(Ros2MsgText(std::string("towsim_msgs/msg/") + name), text) << name;
  }
}

TEST(Ros2Schemas, UnknownTypesAreRejectedWithTheName) {
  for (const std::string bad : {"sensor_msgs::msg::dds_::Imu_", "Odometry", "nav_msgs::Odometry",
                                "nav_msgs::msg::dds_::Odometry", "::msg::dds_::Time_"}) {
    try {
      Ros2TypeName(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(Ros2MsgSchema("sensor_msgs/msg/Imu"), std::invalid_argument);
  EXPECT_THROW(Ros2MsgSchema("nav_msgs/srv/Odometry"), std::invalid_argument);
  EXPECT_EQ(Ros2TypeName("rosgraph_msgs::msg::dds_::Clock_"), "rosgraph_msgs/msg/Clock");
  EXPECT_EQ(Ros2TypeName("towsim_msgs::msg::dds_::CableState_"), "towsim_msgs/msg/CableState");
}

// the rosbag2 metadata record, decoded the way rosbag2_storage's YAML::convert<BagMetadata>
// does (every key it reads for version 8 must be there with the right YAML type)
TEST(Ros2Schemas, Rosbag2MetadataRecordDecodesAsRosbag2ReadsIt) {
  test::TempDir dir;
  const std::string path = (dir.path() / "run.mcap").string();
  constexpr std::uint64_t kT0 = 1'700'000'000'000'000'000ull;  // [ns]
  {
    McapWriter w;
    w.Open(path);
    const auto clock =
        w.AddSchema("rosgraph_msgs/msg/Clock", "ros2msg", Ros2MsgSchema("rosgraph_msgs/msg/Clock"));
    const auto odom =
        w.AddSchema("nav_msgs/msg/Odometry", "ros2msg", Ros2MsgSchema("nav_msgs/msg/Odometry"));
    const std::string qos = "- history: 3\n  depth: 0\n  reliability: 1\n";
    const auto c0 = w.AddChannel(clock, "/clock", "cdr", {{"offered_qos_profiles", qos}});
    const auto c1 = w.AddChannel(odom, "/towsim/towfish/odom", "cdr", {});
    const std::vector<std::uint8_t> payload = {0, 1, 0, 0, 1, 2, 3, 4};
    for (std::uint32_t i = 0; i < 10; ++i) {
      w.Write(c0, i, kT0 + i * 1000, kT0 + i * 1000, payload);
      if (i % 2 == 0) w.Write(c1, i / 2, kT0 + i * 1000 + 5, kT0 + i * 1000, payload);
    }
    AddRosbag2Metadata(w);
    w.Close();
  }
  const McapReader r = McapReader::Open(path);
  ASSERT_EQ(r.metadata().size(), 1u);
  EXPECT_EQ(r.metadata()[0].name, "rosbag2");
  const YAML::Node y = YAML::Load(r.metadata()[0].metadata.at("serialized_metadata"));
  EXPECT_EQ(y["version"].as<int>(), 8);
  EXPECT_EQ(y["storage_identifier"].as<std::string>(), "mcap");
  // last message: /clock at i = 9 (the odometry ends at i = 8, +5 ns)
  EXPECT_EQ(y["duration"]["nanoseconds"].as<std::uint64_t>(), 9000u);
  EXPECT_EQ(y["starting_time"]["nanoseconds_since_epoch"].as<std::uint64_t>(), kT0);
  EXPECT_EQ(y["message_count"].as<std::uint64_t>(), 15u);
  const YAML::Node topics = y["topics_with_message_count"];
  ASSERT_TRUE(topics.IsSequence());
  ASSERT_EQ(topics.size(), 2u);
  EXPECT_EQ(topics[0]["topic_metadata"]["name"].as<std::string>(), "/clock");
  EXPECT_EQ(topics[0]["topic_metadata"]["type"].as<std::string>(), "rosgraph_msgs/msg/Clock");
  EXPECT_EQ(topics[0]["topic_metadata"]["serialization_format"].as<std::string>(), "cdr");
  EXPECT_EQ(topics[0]["topic_metadata"]["offered_qos_profiles"].as<std::string>(),
            "- history: 3\n  depth: 0\n  reliability: 1\n");
  EXPECT_EQ(topics[0]["topic_metadata"]["type_description_hash"].as<std::string>(), "");
  EXPECT_EQ(topics[0]["message_count"].as<std::uint64_t>(), 10u);
  EXPECT_EQ(topics[1]["topic_metadata"]["name"].as<std::string>(), "/towsim/towfish/odom");
  EXPECT_EQ(topics[1]["topic_metadata"]["type"].as<std::string>(), "nav_msgs/msg/Odometry");
  EXPECT_EQ(topics[1]["message_count"].as<std::uint64_t>(), 5u);
  EXPECT_EQ(y["relative_file_paths"].as<std::vector<std::string>>(),
            std::vector<std::string>{"run.mcap"});
  EXPECT_EQ(y["compression_format"].as<std::string>(), "");
  EXPECT_EQ(y["compression_mode"].as<std::string>(), "");
  const YAML::Node files = y["files"];
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0]["path"].as<std::string>(), "run.mcap");
  EXPECT_EQ(files[0]["message_count"].as<std::uint64_t>(), 15u);
  EXPECT_EQ(files[0]["duration"]["nanoseconds"].as<std::uint64_t>(), 9000u);
  EXPECT_TRUE(y["custom_data"].IsMap());
  EXPECT_EQ(y["ros_distro"].as<std::string>(), "");
  // and the summary agrees
  EXPECT_EQ(r.statistics().message_count, 15u);
}

}  // namespace
}  // namespace towsim::io
