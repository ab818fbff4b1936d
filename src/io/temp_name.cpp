#include "io/temp_name.hpp"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "io/fnv1a.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMarker = ".epviz-tmp-";
constexpr std::size_t kTokenDigits = 12;

std::string first_line(const char* file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string make_machine_token() {
  char host[HOST_NAME_MAX + 1] = {};
  if (::gethostname(host, sizeof host) != 0) host[0] = '\0';
  std::error_code ec;
  // "pid:[4026531836]": processes in other PID namespaces (containers) see
  // other pids, even on the same host and boot.
  const std::string pid_namespace = fs::read_symlink("/proc/self/ns/pid", ec).string();
  const std::string identity = std::string(host) + '\n' +
                               first_line("/proc/sys/kernel/random/boot_id") + '\n' + pid_namespace;
  Fnv1a64 hash;
  hash.add(identity);
  return hash.hex().substr(0, kTokenDigits);
}

bool is_hex_digits(std::string_view s) {
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

}  // namespace

const std::string& machine_token() {
  static const std::string token = make_machine_token();
  return token;
}

std::string temporary_suffix(pid_t pid, const std::string& machine) {
  return std::string(kMarker) + machine + "-" + std::to_string(pid);
}

std::optional<TemporaryName> parse_temporary_name(const std::string& name) {
  const auto at = name.rfind(kMarker);
  if (at == std::string::npos || at == 0) return std::nullopt;
  const std::string_view rest = std::string_view(name).substr(at + kMarker.size());
  if (rest.size() < kTokenDigits + 2 || rest[kTokenDigits] != '-') return std::nullopt;
  const std::string_view machine = rest.substr(0, kTokenDigits);
  const std::string_view digits = rest.substr(kTokenDigits + 1);
  if (!is_hex_digits(machine) || digits.size() > 9) return std::nullopt;
  long pid = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    pid = pid * 10 + (c - '0');
  }
  if (pid <= 0) return std::nullopt;
  return TemporaryName{std::string(machine), pid_t(pid)};
}

std::vector<fs::path> remove_stale_temporaries(const fs::path& dir,
                                               fs::file_time_type::duration foreign_age) {
  std::vector<fs::path> removed;
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec);
  if (ec) return removed;
  const auto now = fs::file_time_type::clock::now();
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const auto name = parse_temporary_name(it->path().filename().string());
    if (!name || it->is_symlink(ec) || !it->is_regular_file(ec)) continue;
    if (name->machine == machine_token()) {
      if (name->pid == ::getpid()) continue;
      // kill(pid, 0) fails with ESRCH only when no such process exists; EPERM
      // means it exists under another user.
      if (::kill(name->pid, 0) == 0 || errno != ESRCH) continue;
    } else {
      const auto modified = it->last_write_time(ec);
      if (ec || now - modified < foreign_age) continue;
    }
    if (fs::remove(it->path(), ec)) removed.push_back(it->path());
  }
  return removed;
}

}  // namespace epviz::io
