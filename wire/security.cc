#include "wire/security.h"

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>

#include "dds/ddsrt/log.h"

#ifndef TOWSIM_DDS_SECURITY_PLUGIN_DIR
#define TOWSIM_DDS_SECURITY_PLUGIN_DIR ""
#endif

namespace towsim::wire {
namespace {

bool IsDirectory(const std::string& path) {
  struct stat s {};
  return stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

std::string Absolute(const std::string& path) {
  if (!path.empty() && path[0] == '/') return path;
  char cwd[4096];
  if (getcwd(cwd, sizeof cwd) == nullptr) return path;
  return std::string(cwd) + "/" + path;
}

// "DIR/NAME/" -> "DIR/NAME"
std::string WithoutTrailingSlash(std::string s) {
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

// the messages Cyclone logs while a participant is made (its reason for a refusal)
class LogCapture {
 public:
  LogCapture() { dds_set_log_sink(&LogCapture::Sink, this); }
  ~LogCapture() { dds_set_log_sink(nullptr, nullptr); }  // back to stderr
  LogCapture(const LogCapture&) = delete;
  LogCapture& operator=(const LogCapture&) = delete;

  std::string text() {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }

 private:
  static void Sink(void* self, const dds_log_data_t* data) {
    auto* capture = static_cast<LogCapture*>(self);
    std::lock_guard<std::mutex> lock(capture->mutex_);
    std::string line(data->message, data->size);
    if ((data->priority & (DDS_LC_ERROR | DDS_LC_FATAL)) == 0) {
      if (line.empty() || line.back() != '\n') line += '\n';
      std::fputs(line.c_str(), stderr);  // warnings as Cyclone would print them
      return;
    }
    // one line: OpenSSL's error queue comes on several
    for (char& c : line) {
      if (c == '\n') c = ' ';
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.empty()) return;
    if (!capture->text_.empty()) capture->text_ += "; ";
    capture->text_ += line;
  }

  std::mutex mutex_;
  std::string text_;
};

// one participant at a time through the capture (the log sink is process-wide)
std::mutex g_create_mutex;

// OpenSSL (the library of Cyclone's plugins) names the file Cyclone's message does not: the
// same checks, file by file. Each returns "" if the file passes.
using Bio = std::unique_ptr<BIO, decltype(&BIO_free)>;
using Cert = std::unique_ptr<X509, decltype(&X509_free)>;

std::string OpenSslError() {
  const unsigned long code = ERR_get_error();
  ERR_clear_error();
  if (code == 0) return "not readable";
  char text[256];
  ERR_error_string_n(code, text, sizeof text);
  return text;
}

Cert ReadCertificate(const std::string& path, std::string* error) {
  Bio bio(BIO_new_file(path.c_str(), "r"), &BIO_free);
  Cert cert(bio ? PEM_read_bio_X509(bio.get(), nullptr, nullptr, nullptr) : nullptr, &X509_free);
  if (!cert) *error = path + ": not a PEM certificate (" + OpenSslError() + ")";
  return cert;
}

// `cert` against the CA in `ca_path` (validity period included)
std::string VerifyCertificate(X509* cert, const std::string& cert_path, const std::string& ca_path,
                              X509* ca) {
  std::unique_ptr<X509_STORE, decltype(&X509_STORE_free)> store(X509_STORE_new(), &X509_STORE_free);
  std::unique_ptr<X509_STORE_CTX, decltype(&X509_STORE_CTX_free)> ctx(X509_STORE_CTX_new(),
                                                                      &X509_STORE_CTX_free);
  X509_STORE_add_cert(store.get(), ca);
  X509_STORE_CTX_init(ctx.get(), store.get(), cert, nullptr);
  if (X509_verify_cert(ctx.get()) == 1) return "";
  return cert_path + ": " + X509_verify_cert_error_string(X509_STORE_CTX_get_error(ctx.get())) +
         " (against " + ca_path + ")";
}

// an S/MIME document (clear text, detached signature) signed by the CA `ca`
std::string VerifyDocument(const std::string& path, const std::string& ca_path, X509* ca) {
  Bio bio(BIO_new_file(path.c_str(), "r"), &BIO_free);
  BIO* content = nullptr;
  std::unique_ptr<PKCS7, decltype(&PKCS7_free)> p7(
      bio ? SMIME_read_PKCS7(bio.get(), &content) : nullptr, &PKCS7_free);
  Bio content_owner(content, &BIO_free);
  if (!p7) return path + ": not an S/MIME document (" + OpenSslError() + ")";
  std::unique_ptr<X509_STORE, decltype(&X509_STORE_free)> store(X509_STORE_new(), &X509_STORE_free);
  X509_STORE_add_cert(store.get(), ca);
  Bio out(BIO_new(BIO_s_mem()), &BIO_free);
  if (PKCS7_verify(p7.get(), nullptr, store.get(), content, out.get(), PKCS7_TEXT) != 1) {
    return path + ": its signature does not verify against " + ca_path + " (" + OpenSslError() +
           ")";
  }
  return "";
}

// the first file of `f` that fails a check, and why; "" if every file passes
std::string Diagnose(const SecurityFiles& f) {
  std::string e;
  const Cert identity_ca = ReadCertificate(f.identity_ca, &e);
  if (!identity_ca) return e;
  const Cert cert = ReadCertificate(f.certificate, &e);
  if (!cert) return e;
  if (e = VerifyCertificate(cert.get(), f.certificate, f.identity_ca, identity_ca.get());
      !e.empty()) {
    return e;
  }
  {
    Bio bio(BIO_new_file(f.private_key.c_str(), "r"), &BIO_free);
    std::unique_ptr<EVP_PKEY, decltype(&EVP_PKEY_free)> key(
        bio ? PEM_read_bio_PrivateKey(bio.get(), nullptr, nullptr, nullptr) : nullptr,
        &EVP_PKEY_free);
    if (!key) return f.private_key + ": not a PEM private key (" + OpenSslError() + ")";
    if (X509_check_private_key(cert.get(), key.get()) != 1) {
      ERR_clear_error();
      return f.private_key + ": not the key of " + f.certificate;
    }
  }
  const Cert permissions_ca = ReadCertificate(f.permissions_ca, &e);
  if (!permissions_ca) return e;
  if (e = VerifyDocument(f.governance, f.permissions_ca, permissions_ca.get()); !e.empty()) {
    return e;
  }
  return VerifyDocument(f.permissions, f.permissions_ca, permissions_ca.get());
}

void SetLibrary(dds_qos_t* qos, const std::string& prefix, const std::string& library,
                const char* init, const char* finalize) {
  const std::string dir = SecurityPluginDirectory();
  const std::string path = dir.empty() ? library : dir + "/lib" + library + ".so";
  dds_qset_prop(qos, (prefix + ".library.path").c_str(), path.c_str());
  dds_qset_prop(qos, (prefix + ".library.init").c_str(), init);
  dds_qset_prop(qos, (prefix + ".library.finalize").c_str(), finalize);
}

}  // namespace

const char* SecurityPluginDirectory() { return TOWSIM_DDS_SECURITY_PLUGIN_DIR; }

SecurityFiles FindSecurityFiles(const std::string& identity, Admit admit) {
  const std::string where = "--security " + identity;
  if (identity.empty()) throw SecurityError("--security needs DIR/NAME");
  const std::string path = Absolute(WithoutTrailingSlash(identity));
  if (!IsDirectory(path)) {
    throw SecurityError(where + ": no such directory (make it with scripts/security.sh DIR NAME)");
  }
  const size_t slash = path.rfind('/');
  const std::string dir = slash == 0 ? "/" : path.substr(0, slash);
  SecurityFiles f;
  f.identity_ca = dir + "/identity_ca.pem";
  f.permissions_ca = dir + "/permissions_ca.pem";
  f.governance = dir + (admit == Admit::kOpenOutputs ? "/governance_open.p7s" : "/governance.p7s");
  f.certificate = path + "/cert.pem";
  f.private_key = path + "/key.pem";
  f.permissions = path + "/permissions.p7s";
  for (const std::string* file : {&f.identity_ca, &f.permissions_ca, &f.governance, &f.certificate,
                                  &f.private_key, &f.permissions}) {
    if (access(file->c_str(), F_OK) != 0) {
      throw SecurityError(where + ": " + *file + ": no such file" +
                          (file == &f.governance && admit == Admit::kOpenOutputs
                               ? " (the scene's security.open_outputs needs a DIR made by "
                                 "scripts/security.sh --open-outputs)"
                               : ""));
    }
    if (access(file->c_str(), R_OK) != 0)
      throw SecurityError(where + ": " + *file + ": not readable");
  }
  return f;
}

void AddSecurityProperties(const SecurityFiles& files, dds_qos_t* qos) {
  SetLibrary(qos, "dds.sec.auth", "dds_security_auth", "init_authentication",
             "finalize_authentication");
  SetLibrary(qos, "dds.sec.crypto", "dds_security_crypto", "init_crypto", "finalize_crypto");
  SetLibrary(qos, "dds.sec.access", "dds_security_ac", "init_access_control",
             "finalize_access_control");
  const auto file = [](const std::string& path) { return "file:" + path; };
  dds_qset_prop(qos, "dds.sec.auth.identity_ca", file(files.identity_ca).c_str());
  dds_qset_prop(qos, "dds.sec.auth.identity_certificate", file(files.certificate).c_str());
  dds_qset_prop(qos, "dds.sec.auth.private_key", file(files.private_key).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions_ca", file(files.permissions_ca).c_str());
  dds_qset_prop(qos, "dds.sec.access.governance", file(files.governance).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions", file(files.permissions).c_str());
}

dds_entity_t CreateSecureParticipant(uint32_t domain, const std::string& identity,
                                     const dds_qos_t* qos, Admit admit) {
  const std::string where = "DDS domain " + std::to_string(domain);
  if (identity.empty()) {
    const dds_entity_t p = dds_create_participant(domain, qos, nullptr);
    if (p < 0) {
      throw std::runtime_error("creating a participant in " + where + ": " + dds_strretcode(p));
    }
    return p;
  }
  const SecurityFiles files = FindSecurityFiles(identity, admit);
  // Cyclone accepts a private key that is not the certificate's at creation (every handshake
  // fails later): refuse it here
  if (const std::string e = Diagnose(files); e.find(files.private_key) == 0) {
    throw SecurityError("--security " + identity + ": " + e);
  }
  std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)> q(dds_create_qos(), &dds_delete_qos);
  if (qos != nullptr) dds_copy_qos(q.get(), qos);
  AddSecurityProperties(files, q.get());

  std::lock_guard<std::mutex> lock(g_create_mutex);
  dds_entity_t p = 0;
  std::string log;
  {
    LogCapture capture;
    p = dds_create_participant(domain, q.get(), nullptr);
    log = capture.text();
  }
  if (p < 0) {
    // "<file>: <why>" where OpenSSL finds the fault, then Cyclone's reason
    std::string file = Diagnose(files);
    if (file.empty()) file = "its files verify with OpenSSL (see Cyclone's reason)";
    throw SecurityError("--security " + identity + ": " + file + "; Cyclone refused the " +
                        "participant in " + where + " (" + dds_strretcode(p) +
                        "): " + (log.empty() ? std::string("no reason logged") : log));
  }
  // errors Cyclone logged that did not stop it: as it would have printed them
  if (!log.empty()) std::fprintf(stderr, "%s\n", log.c_str());
  return p;
}

}  // namespace towsim::wire
