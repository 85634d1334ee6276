// `rift list`: the packs, rules, interactions and criteria compiled into this
// simulator, with their parameters.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "rift/pack/pack.hpp"

namespace rift::cli {

namespace {

std::string value_text(const Value& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Real> || std::is_same_v<T, std::int64_t>) {
          return fmt::format("{}", x);
        } else if constexpr (std::is_same_v<T, Bool>) {
          return x ? "true" : "false";
        } else if constexpr (std::is_same_v<T, Vec3>) {
          return fmt::format("[{}, {}, {}]", x.x(), x.y(), x.z());
        } else {
          return "mat3";
        }
      },
      v);
}

void print_components(const char* title, const std::vector<ComponentSpec>& list) {
  if (list.empty()) return;
  fmt::print("  {}:\n", title);
  for (const ComponentSpec& c : list) {
    fmt::print("    {}{}\n", c.name, c.description.empty() ? "" : "  — " + c.description);
    for (const ParamSpec& p : c.params) {
      fmt::print("      {} : {}{}{}\n", p.name, to_string(p.type),
                 p.default_value ? " = " + value_text(*p.default_value) : " (required)",
                 p.description.empty() ? "" : "  " + p.description);
    }
  }
}

}  // namespace

CLI::App* add_list_command(CLI::App& app) {
  return app.add_subcommand(
      "list", "List the rule packs, rules, interactions and criteria of this simulator");
}

int run_list(const PackRegistry& packs) {
  if (packs.packs().empty()) {
    fmt::print("no rule packs are compiled into this executable\n");
    return 0;
  }
  for (const auto& p : packs.packs()) {
    fmt::print("pack {} ({}D){}\n", p->name(), p->dimension(),
               p->description().empty() ? "" : "  — " + p->description());
    print_components("interactions", p->catalog().interactions);
    print_components("criteria", p->catalog().criteria);
    const auto rules = p->rule_names();
    if (!rules.empty()) {
      fmt::print("  rules:\n");
      for (const std::string& r : rules)
        fmt::print("    {}\n", r);
    }
  }
  return 0;
}

}  // namespace rift::cli
