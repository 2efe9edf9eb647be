// wire/security: the files of an identity, the QoS properties handed to Cyclone's
// plugins, and the refusal of a key that is not the certificate's, all before any DDS traffic
// (no participant is created here; tests/integration/security_integration_test.cc runs them).
// Identities from scripts/security.sh in a temp dir. The gtest names avoid the word that
// `ctest -R Security` selects (the integration tests).

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "wire/security.h"

namespace towsim::wire {
namespace {

namespace fs = std::filesystem;

class IdentityFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    keys_ = tmp_.path() / "keys";
    const std::string command = std::string(TOWSIM_SOURCE_DIR) + "/scripts/security.sh '" +
                                keys_.string() + "' ctl:towfish other 2>/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  std::string Id(const std::string& name) const { return (keys_ / name).string(); }

  test::TempDir tmp_;
  fs::path keys_;
};

std::string Message(const std::string& identity) {
  try {
    FindSecurityFiles(identity);
  } catch (const SecurityError& e) {
    return e.what();
  }
  return "";
}

TEST_F(IdentityFilesTest, FilesOfDirAndName) {
  const SecurityFiles f = FindSecurityFiles(Id("ctl") + "/");  // a trailing slash is fine
  EXPECT_EQ(f.identity_ca, (keys_ / "identity_ca.pem").string());
  EXPECT_EQ(f.permissions_ca, (keys_ / "permissions_ca.pem").string());
  EXPECT_EQ(f.governance, (keys_ / "governance.p7s").string());
  EXPECT_EQ(f.certificate, (keys_ / "ctl/cert.pem").string());
  EXPECT_EQ(f.private_key, (keys_ / "ctl/key.pem").string());
  EXPECT_EQ(f.permissions, (keys_ / "ctl/permissions.p7s").string());
  // open outputs need the node's governance_open.p7s (security.sh --open-outputs)
  try {
    FindSecurityFiles(Id("ctl"), Admit::kOpenOutputs);
    FAIL() << "no SecurityError";
  } catch (const SecurityError& e) {
    EXPECT_NE(
        std::string(e.what()).find((keys_ / "governance_open.p7s").string() + ": no such file"),
        std::string::npos)
        << e.what();
  }
}

TEST_F(IdentityFilesTest, MissingDirectoryOrFileIsNamed) {
  EXPECT_EQ(Message(Id("nobody")),
            "--security " + Id("nobody") +
                ": no such directory (make it with scripts/security.sh DIR NAME)");
  fs::remove(keys_ / "ctl/permissions.p7s");
  EXPECT_EQ(Message(Id("ctl")), "--security " + Id("ctl") + ": " +
                                    (keys_ / "ctl/permissions.p7s").string() + ": no such file");
  EXPECT_EQ(Message(""), "--security needs DIR/NAME");
}

TEST_F(IdentityFilesTest, PropertiesNameTheFilesAndThePlugins) {
  const SecurityFiles f = FindSecurityFiles(Id("ctl"));
  dds_qos_t* qos = dds_create_qos();
  AddSecurityProperties(f, qos);
  const auto prop = [qos](const char* name) {
    char* value = nullptr;
    std::string out = dds_qget_prop(qos, name, &value) ? value : "<absent>";
    dds_free(value);
    return out;
  };
  EXPECT_EQ(prop("dds.sec.auth.identity_ca"), "file:" + f.identity_ca);
  EXPECT_EQ(prop("dds.sec.auth.identity_certificate"), "file:" + f.certificate);
  EXPECT_EQ(prop("dds.sec.auth.private_key"), "file:" + f.private_key);
  EXPECT_EQ(prop("dds.sec.access.permissions_ca"), "file:" + f.permissions_ca);
  EXPECT_EQ(prop("dds.sec.access.governance"), "file:" + f.governance);
  EXPECT_EQ(prop("dds.sec.access.permissions"), "file:" + f.permissions);
  EXPECT_EQ(prop("dds.sec.auth.library.init"), "init_authentication");
  EXPECT_EQ(prop("dds.sec.access.library.finalize"), "finalize_access_control");
  EXPECT_EQ(prop("dds.sec.crypto.library.init"), "init_crypto");
  // the plugins by path where the build found them
  const std::string dir = SecurityPluginDirectory();
  if (!dir.empty()) {
    EXPECT_EQ(prop("dds.sec.auth.library.path"), dir + "/libdds_security_auth.so");
    EXPECT_TRUE(fs::exists(dir + "/libdds_security_auth.so"));
  }
  dds_delete_qos(qos);
}

// Cyclone would accept it and fail every handshake: refused before a participant exists
TEST_F(IdentityFilesTest, KeyOfAnotherIdentityIsRefused) {
  fs::copy_file(keys_ / "other/key.pem", keys_ / "ctl/key.pem",
                fs::copy_options::overwrite_existing);
  try {
    CreateSecureParticipant(0, Id("ctl"));
    FAIL() << "no SecurityError";
  } catch (const SecurityError& e) {
    EXPECT_EQ(std::string(e.what()), "--security " + Id("ctl") + ": " +
                                         (keys_ / "ctl/key.pem").string() + ": not the key of " +
                                         (keys_ / "ctl/cert.pem").string());
  }
}

}  // namespace
}  // namespace towsim::wire
