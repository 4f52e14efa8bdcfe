#include "ports_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/runtime_error.h"
#include "exit_codes.h"
#include "port_list.h"

namespace rb::cli {

namespace {

int executePorts(const std::vector<std::string>& devices) {
  std::vector<drivers::PortInfo> ports;
  try {
    if (devices.empty()) {
      ports = drivers::listPorts();
    } else {
      for (const std::string& d : devices) ports.push_back(drivers::describePort(d));
    }
  } catch (const RuntimeError& e) {
    std::fprintf(stderr, "rb ports: %s\n", e.what());
    return run::exitcode::kIoError;
  }
  std::string table = drivers::formatPorts(ports);
  std::fwrite(table.data(), 1, table.size(), stdout);
  return run::exitcode::kOk;
}

}  // namespace

void addPortsCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto devices = std::make_shared<std::vector<std::string>>();
  CLI::App* ports = app.add_subcommand(
      "ports", "List the serial ports (USB, Bluetooth) and the --port number of each");
  if (!withOptions) return;
  ports->add_option("device", *devices,
                    "Describe these devices instead of listing the system's ports");
  ports->footer(
      "--port N (and rCommPort N) opens the first of /dev/rfcomm(N-1), /dev/ttyUSB(N-1), "
      "/dev/ttyACM(N-1), /dev/ttyS(N-1) that exists; '-' in the list: only the device's path "
      "opens it (--port /dev/...). Exit status: 0, 74 when the ports cannot be listed.");
  ports->callback([devices, &exitCode] { exitCode = executePorts(*devices); });
}

}  // namespace rb::cli
