#pragma once
// A small command-line parser shared by the lenslab subcommands: --name value, --name=value,
// flags, positionals, and --help text generated from the declarations.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ArgParser {
public:
    ArgParser(std::string command, std::string synopsis, std::string description);
    void positional(const std::string& name, const std::string& help);
    void option(const std::string& name, const std::string& value, const std::string& help);
    void flag(const std::string& name, const std::string& help);

    // Throws UsageError for unknown options, missing values or missing positionals.
    // Returns false when --help was asked for (the caller prints help()).
    bool parse(const std::vector<std::string>& args);
    std::string help() const;

    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::string get(const std::string& name, const std::string& fallback = "") const;
    std::optional<double> number(const std::string& name) const;  // UsageError if not a number
    std::optional<long> integer(const std::string& name) const;    // UsageError if not an integer
    const std::string& arg(std::size_t i) const { return positionals_.at(i); }
    std::size_t argCount() const { return positionals_.size(); }

private:
    struct Decl {
        std::string name, value, help;
    };
    std::string command_, synopsis_, description_;
    std::vector<Decl> positionalDecls_, optionDecls_;
    std::map<std::string, std::string> values_;
    std::vector<std::string> positionals_;
};

// Parses "inf"/"infinity" or a number of millimetres; UsageError naming `what` otherwise.
double parseDistance(const std::string& text, const std::string& what);

}  // namespace lenslab
