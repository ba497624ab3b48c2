// `robowire dissector <buwizz3|navbot|osp|all> [--output DIR]`: writes the
// Wireshark Lua plugins (tools/dissector.hpp).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli.hpp"
#include "dissector.hpp"

namespace robowire::cli {

void add_dissector_command(CLI::App& app) {
    struct options {
        std::string protocol;
        std::string dir = ".";
    };
    auto opt = std::make_shared<options>();
    auto* cmd =
        app.add_subcommand("dissector", "write Wireshark Lua plugins (DIR/robowire_<protocol>.lua); docs/wireshark.md");
    cmd->add_option("protocol", opt->protocol, "buwizz3, navbot, osp or all")
        ->required()
        ->check(CLI::IsMember({"buwizz3", "navbot", "osp", "all"}));
    cmd->add_option("--output", opt->dir, "folder to write into, created if missing (default: the current folder)");
    cmd->final_callback([opt] {
        std::error_code ec;
        std::filesystem::create_directories(opt->dir, ec);
        if (ec) {
            std::fprintf(stderr, "robowire: cannot create %s: %s\n", opt->dir.c_str(), ec.message().c_str());
            throw CLI::RuntimeError(1);
        }
        const int rc = robowire::tool::write_dissectors(opt->protocol, opt->dir.c_str(), stderr);
        if (rc != 0) throw CLI::RuntimeError("the plugins were not written", rc);
    });
}

}  // namespace robowire::cli
