#include "port_names.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>
#include <vector>

#include "base/runtime_error.h"

namespace fs = std::filesystem;

namespace rb::drivers {

namespace {

// Linux device families, most likely first: a robot paired over Bluetooth and bound with
// `rfcomm bind`, then USB serial adapters, USB CDC boards, and built-in UARTs last because
// their device nodes exist whether or not a port is there.
constexpr const char* kLinuxFamilies[] = {"rfcomm", "ttyUSB", "ttyACM", "ttyS"};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? (i + 1 == v.size() ? " or " : ", ") : "") + v[i];
  return s;
}

/// The port number `text` names ("5", "COM5", "com5"), or -1 when it names none.
int64_t portNumber(const std::string& text) {
  std::string digits = text;
  if (digits.size() > 3 && std::tolower(static_cast<unsigned char>(digits[0])) == 'c' &&
      std::tolower(static_cast<unsigned char>(digits[1])) == 'o' &&
      std::tolower(static_cast<unsigned char>(digits[2])) == 'm')
    digits = digits.substr(3);
  if (digits.empty() || digits.size() > 6) return -1;
  for (char c : digits)
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
  return std::stoll(digits);
}

}  // namespace

PortScheme nativePortScheme() {
#ifdef __APPLE__
  return PortScheme::MacOS;
#else
  return PortScheme::Linux;
#endif
}

std::string devicePathForPort(int64_t n, PortScheme scheme, const std::string& devDir) {
  if (n < 1)
    throw RuntimeError("port " + std::to_string(n) +
                       ": port numbers start at 1 (rCommPort 0 switches back to the simulator)");
  std::error_code ec;
  if (scheme == PortScheme::Linux) {
    std::vector<std::string> tried;
    for (const char* family : kLinuxFamilies) {
      std::string path = (fs::path(devDir) / (family + std::to_string(n - 1))).string();
      if (fs::exists(path, ec)) return path;
      tried.push_back(path);
    }
    throw RuntimeError("no serial device for port " + std::to_string(n) + " (looked for " +
                       join(tried) + "); name the device with --port PATH");
  }
  std::vector<std::string> devices;
  for (const auto& entry : fs::directory_iterator(devDir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.rfind("cu.", 0) == 0) devices.push_back(entry.path().string());
  }
  std::sort(devices.begin(), devices.end());
  if (static_cast<size_t>(n) > devices.size())
    throw RuntimeError("no serial device for port " + std::to_string(n) + ": " + devDir +
                       " has " + std::to_string(devices.size()) +
                       " cu.* devices; name the device with --port PATH");
  return devices[static_cast<size_t>(n - 1)];
}

std::string resolvePortOption(const std::string& text, PortScheme scheme, const std::string& devDir) {
  int64_t n = portNumber(text);
  return n >= 0 ? devicePathForPort(n, scheme, devDir) : text;
}

}  // namespace rb::drivers
