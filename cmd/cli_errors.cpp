#include "cli_errors.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "exit_codes.h"
#include "lang/suggest.h"

namespace rb::cli {

namespace {

std::string commandName(const CLI::App* sub) {
  return sub ? "rb " + sub->get_name() : std::string("rb");
}

int usageError(const CLI::App* sub, const std::string& message) {
  std::string where = sub ? "rb " + sub->get_name() + " --help" : std::string("rb --help");
  std::fprintf(stderr, "%s: error: %s\nRun '%s' for %s.\n", commandName(sub).c_str(),
               message.c_str(), where.c_str(), sub ? "its options" : "the commands");
  return run::exitcode::kUsage;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& names) {
  std::vector<std::string_view> views(names.begin(), names.end());
  std::string near = closestMatch(word, views, false);
  return near.empty() ? "" : "; did you mean '" + near + "'?";
}

std::vector<std::string> commandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (!sub->get_group().empty()) names.push_back(sub->get_name());  // not the hidden ones
  names.push_back("help");
  return names;
}

/// The option of `sub` spelled `word` ("--seed", "-o"), or nullptr.
const CLI::Option* findOption(const CLI::App& sub, std::string_view word) {
  for (const CLI::Option* opt : sub.get_options()) {
    if (word.size() > 2 && word.substr(0, 2) == "--") {
      for (const std::string& n : opt->get_lnames())
        if (word.substr(2) == n) return opt;
    } else if (word.size() == 2 && word[0] == '-') {
      for (const std::string& n : opt->get_snames())
        if (word.substr(1) == n) return opt;
    }
  }
  return nullptr;
}

std::vector<std::string> optionNames(const CLI::App& sub) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : sub.get_options()) {
    for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : opt->get_snames()) names.push_back("-" + n);
  }
  return names;
}

/// The program `word` names when it stands where a command belongs (`rb square.bas`, or
/// `rb square` beside square.bas), or "" when it names none.
std::string programNamed(std::string_view word) {
  namespace fs = std::filesystem;
  auto endsWithBas = [](std::string_view w) {
    if (w.size() < 4) return false;
    std::string tail(w.substr(w.size() - 4));
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == ".bas";
  };
  if (endsWithBas(word)) return std::string(word);
  std::error_code ec;
  std::string withBas = std::string(word) + ".bas";
  if (!word.empty() && fs::is_regular_file(withBas, ec)) return withBas;
  return "";
}

/// `rb run FILE ARGS...` as it could be typed again (arguments with spaces or quotes quoted).
std::string runCommandLine(const std::string& file, int argc, char** argv) {
  auto shellWord = [](std::string_view a) {
    bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                   "0123456789-_./=:,+%@") == std::string_view::npos;
    if (plain) return std::string(a);
    std::string q = "\"";
    for (char c : a) {
      if (c == '"' || c == '\\' || c == '$' || c == '`') q += '\\';
      q += c;
    }
    return q + '"';
  };
  std::string line = "rb run " + shellWord(file);
  for (int i = 2; i < argc; ++i) line += " " + shellWord(argv[i]);
  return line;
}

bool looksLikeOption(std::string_view a) {
  if (a.size() < 2 || a[0] != '-') return false;
  // "-5" or "-.5" is a number (a negative value), not an option.
  return !(std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.');
}

}  // namespace

std::optional<int> precheckCommandLine(CLI::App& app, int argc, char** argv) {
  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return run::exitcode::kUsage;
  }
  std::string_view first = argv[1];
  if (first == "help") {
    if (argc == 2) {
      std::fputs(app.help().c_str(), stdout);
      return run::exitcode::kOk;
    }
    std::string wanted = argv[2];
    for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == wanted) {
        std::fputs(sub->help().c_str(), stdout);
        return run::exitcode::kOk;
      }
    return usageError(nullptr, "'" + wanted + "' is not an rb command" +
                                   didYouMean(wanted, commandNames(app)));
  }
  if (looksLikeOption(first)) return std::nullopt;  // --help, --version; CLI11 reports the rest
  CLI::App* sub = nullptr;
  for (CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    if (s->get_name() == first) sub = s;
  if (!sub) {
    // A program where the command belongs: the command is most likely run.
    if (std::string program = programNamed(first); !program.empty())
      return usageError(nullptr, "'" + std::string(first) + "' is not an rb command; did you mean '" +
                                     runCommandLine(program, argc, argv) + "'?");
    return usageError(nullptr, "'" + std::string(first) + "' is not an rb command" +
                                   didYouMean(first, commandNames(app)));
  }
  // Options of the command: an unknown one is named (CLI11 would blame the file after it).
  for (int i = 2; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--") break;
    if (!looksLikeOption(a)) continue;
    std::string_view name = a.substr(0, a.find('='));
    const CLI::Option* opt = findOption(*sub, name);
    if (!opt) {
      if (name == "--help" || name == "-h" || name == "--help-all") continue;
      return usageError(sub, "unknown option '" + std::string(name) + "'" +
                                 didYouMean(name, optionNames(*sub)));
    }
    // An option with a value written apart takes the next word, even one that starts with '-'.
    if (opt->get_type_size_max() > 0 && name.size() == a.size()) ++i;
  }
  return std::nullopt;
}

void useRbFailureMessages(CLI::App& app) {
  app.failure_message([](const CLI::App* main, const CLI::Error& e) -> std::string {
    std::vector<CLI::App*> parsed = main->get_subcommands();
    const CLI::App* sub = parsed.empty() ? nullptr : parsed.back();
    std::string message = e.what();
    if (message == "file is required") message = "no program file given";
    if (!message.empty()) message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
    std::string where = sub ? "rb " + sub->get_name() + " --help" : std::string("rb --help");
    return commandName(sub) + ": error: " + message + "\nRun '" + where + "' for " +
           (sub ? "its options" : "the commands") + ".\n";
  });
}

}  // namespace rb::cli
