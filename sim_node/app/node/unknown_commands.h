#pragma once
// Commands on the topic of a body that takes none (docs/topics.md): a controller writing
// rt<ns>/ghost/command, for a body the scene does not have or one that takes no commands,
// would otherwise be ignored without a word. The node watches the writers announced in
// discovery (the DCPSPublication built-in topic); for each ActuatorCommand writer on such a
// topic it creates a reader, and every sample taken counts as a received and rejected
// command, reported in SimStatus (commands_received, commands_rejected, message) and the
// summary, as ActuatorCommand.msg says.

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "dds/entities.h"
#include "dds/messages.h"
#include "wire/topic_names.h"

namespace towsim::app {

class UnknownCommands {
 public:
  // `ns`: the namespace; `known`: the bodies that take commands (their readers exist)
  UnknownCommands(const dds::Participant& participant, const std::string& ns,
                  std::vector<std::string> known);

  // takes new announcements and the commands on unknown topics; returns how many commands
  // were taken now
  int Poll();

  std::uint64_t count() const { return count_; }
  // "ghost: command rejected (no body ghost that takes commands in this scene)"
  const std::string& last_event() const { return last_event_; }

 private:
  struct Watched {
    std::string body;
    std::unique_ptr<dds::Topic> topic;
    std::unique_ptr<dds::Reader<dds::ActuatorCommandMsg>> reader;
  };

  const dds::Participant& participant_;
  wire::TopicNames names_;
  std::set<std::string> known_;
  dds::Entity publications_;  // reader of DCPSPublication
  std::set<std::string> watched_names_;
  std::vector<Watched> watched_;
  std::uint64_t count_ = 0;
  std::string last_event_;
};

}  // namespace towsim::app
