#include "port_list.h"

#include <libserialport.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "base/runtime_error.h"

namespace rb::drivers {

namespace {

std::string text(const char* s) { return s ? std::string(s) : std::string(); }

/// Fills `info` from a libserialport port.
void fill(PortInfo& info, sp_port* port) {
  info.description = text(sp_get_port_description(port));
  switch (sp_get_port_transport(port)) {
    case SP_TRANSPORT_USB: {
      info.transport = "usb";
      int vid = -1, pid = -1;
      if (sp_get_port_usb_vid_pid(port, &vid, &pid) == SP_OK) {
        info.vid = vid;
        info.pid = pid;
      }
      info.manufacturer = text(sp_get_port_usb_manufacturer(port));
      info.product = text(sp_get_port_usb_product(port));
      info.serial = text(sp_get_port_usb_serial(port));
      break;
    }
    case SP_TRANSPORT_BLUETOOTH:
      info.transport = "bluetooth";
      info.bluetoothAddress = text(sp_get_port_bluetooth_address(port));
      break;
    default: info.transport = "native"; break;
  }
}

std::string hex4(int v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(v) & 0xFFFF);
  return buf;
}

/// What a port is, in one phrase.
std::string what(const PortInfo& p) {
  std::string out;
  auto add = [&out](const std::string& s) {
    if (s.empty()) return;
    if (!out.empty()) out += ", ";
    out += s;
  };
  if (p.transport == "usb") {
    std::string usb = "USB";
    if (p.vid >= 0) usb += " " + hex4(p.vid) + ":" + hex4(p.pid);
    add(usb);
    std::string name = p.manufacturer;
    if (!p.product.empty()) name += (name.empty() ? "" : " ") + p.product;
    add(name);
    if (!p.serial.empty()) add("serial " + p.serial);
  } else if (p.transport == "bluetooth") {
    add("Bluetooth" + (p.bluetoothAddress.empty() ? "" : " " + p.bluetoothAddress));
  } else if (p.transport == "rfcomm") {
    add("Bluetooth RFCOMM binding (rfcomm bind)");
  } else if (p.transport == "native") {
    add("serial port");
  } else {
    add("not a serial port libserialport knows");
  }
  // The driver's description, when it says more than the device's name.
  std::string name = std::filesystem::path(p.device).filename().string();
  if (!p.description.empty() && p.description != p.product && p.description != name &&
      p.transport != "usb")
    add(p.description);
  return out;
}

}  // namespace

std::vector<std::string> rfcommDevices(const std::string& devDir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(devDir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.rfind("rfcomm", 0) == 0 && name.size() > 6 &&
        name.find_first_not_of("0123456789", 6) == std::string::npos)
      out.push_back(entry.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<int64_t> portNumberOf(const std::string& device, PortScheme scheme,
                                    const std::string& devDir) {
  for (int64_t n = 1; n <= 256; ++n) {
    try {
      if (devicePathForPort(n, scheme, devDir) == device) return n;
    } catch (const RuntimeError&) {
      // no device for n
    }
  }
  return std::nullopt;
}

std::vector<PortInfo> listPorts(PortScheme scheme, const std::string& devDir) {
  std::vector<PortInfo> out;
  sp_port** list = nullptr;
  if (sp_list_ports(&list) != SP_OK) {
    char* why = sp_last_error_message();
    std::string message = "cannot list the serial ports: " + text(why);
    sp_free_error_message(why);
    throw RuntimeError(message);
  }
  for (sp_port** p = list; *p; ++p) {
    PortInfo info;
    info.device = text(sp_get_port_name(*p));
    fill(info, *p);
    out.push_back(std::move(info));
  }
  sp_free_port_list(list);
  for (const std::string& dev : rfcommDevices(devDir)) {
    bool listed = std::any_of(out.begin(), out.end(), [&](const PortInfo& i) { return i.device == dev; });
    if (listed) continue;
    PortInfo info;
    info.device = dev;
    info.transport = "rfcomm";
    out.push_back(std::move(info));
  }
  std::sort(out.begin(), out.end(),
            [](const PortInfo& a, const PortInfo& b) { return a.device < b.device; });
  for (PortInfo& p : out) p.number = portNumberOf(p.device, scheme, devDir);
  return out;
}

PortInfo describePort(const std::string& device, PortScheme scheme, const std::string& devDir) {
  PortInfo info;
  info.device = device;
  info.transport = "unknown";
  sp_port* port = nullptr;
  if (sp_get_port_by_name(device.c_str(), &port) == SP_OK) {
    fill(info, port);
    sp_free_port(port);
  }
  std::string name = std::filesystem::path(device).filename().string();
  if (info.transport != "usb" && name.rfind("rfcomm", 0) == 0) info.transport = "rfcomm";
  info.number = portNumberOf(device, scheme, devDir);
  return info;
}

std::string formatPorts(const std::vector<PortInfo>& ports) {
  if (ports.empty()) return "no serial ports found\n";
  size_t width = 6;
  for (const PortInfo& p : ports) width = std::max(width, p.device.size());
  auto line = [&](const std::string& number, const std::string& device, const std::string& w) {
    std::string l = number;
    l.resize(8, ' ');
    l += device;
    l.resize(8 + width + 2, ' ');
    l += w;
    while (!l.empty() && l.back() == ' ') l.pop_back();
    return l + "\n";
  };
  std::string out = line("--port", "device", "what");
  for (const PortInfo& p : ports)
    out += line(p.number ? std::to_string(*p.number) : "-", p.device, what(p));
  return out;
}

}  // namespace rb::drivers
