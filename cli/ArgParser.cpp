#include "ArgParser.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace lenslab {

ArgParser::ArgParser(std::string command, std::string synopsis, std::string description)
    : command_(std::move(command)), synopsis_(std::move(synopsis)), description_(std::move(description)) {}

void ArgParser::positional(const std::string& name, const std::string& help) {
    positionalDecls_.push_back({name, "", help});
}

void ArgParser::option(const std::string& name, const std::string& value, const std::string& help) {
    optionDecls_.push_back({name, value, help});
}

void ArgParser::flag(const std::string& name, const std::string& help) { optionDecls_.push_back({name, "", help}); }

bool ArgParser::parse(const std::vector<std::string>& args) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-h" || a == "--help") return false;
        if (a.size() > 1 && a[0] == '-' && !(std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.')) {
            std::string name = a, value;
            bool inlineValue = false;
            if (auto eq = a.find('='); eq != std::string::npos) {
                name = a.substr(0, eq);
                value = a.substr(eq + 1);
                inlineValue = true;
            }
            const Decl* decl = nullptr;
            for (const Decl& d : optionDecls_)
                if (d.name == name) decl = &d;
            if (!decl) throw UsageError(command_ + ": unknown option " + name + " (see --help)");
            if (decl->value.empty()) {
                if (inlineValue) throw UsageError(command_ + ": " + name + " takes no value");
                values_[name] = "1";
            } else {
                if (!inlineValue) {
                    if (i + 1 >= args.size()) throw UsageError(command_ + ": " + name + " needs a value " + decl->value);
                    value = args[++i];
                }
                values_[name] = value;
            }
        } else {
            positionals_.push_back(a);
        }
    }
    if (positionals_.size() < positionalDecls_.size())
        throw UsageError(command_ + ": missing " + positionalDecls_[positionals_.size()].name + " (see --help)");
    if (positionals_.size() > positionalDecls_.size())
        throw UsageError(command_ + ": unexpected argument '" + positionals_[positionalDecls_.size()] + "'");
    return true;
}

std::string ArgParser::help() const {
    std::ostringstream s;
    s << "usage: lenslab " << command_ << " " << synopsis_ << "\n\n" << description_ << "\n";
    if (!positionalDecls_.empty() || !optionDecls_.empty()) s << "\n";
    auto row = [&](const std::string& left, const std::string& help) {
        s << "  " << left;
        for (std::size_t k = left.size(); k < 26; ++k) s << ' ';
        s << " " << help << "\n";
    };
    for (const Decl& d : positionalDecls_) row(d.name, d.help);
    for (const Decl& d : optionDecls_) row(d.value.empty() ? d.name : d.name + " " + d.value, d.help);
    row("-h, --help", "show this help");
    return s.str();
}

std::string ArgParser::get(const std::string& name, const std::string& fallback) const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

std::optional<double> ArgParser::number(const std::string& name) const {
    if (!has(name)) return std::nullopt;
    const std::string v = get(name);
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
        throw UsageError(command_ + ": " + name + " expects a number, got '" + v + "'");
    return x;
}

std::optional<long> ArgParser::integer(const std::string& name) const {
    if (!has(name)) return std::nullopt;
    const std::string v = get(name);
    char* end = nullptr;
    errno = 0;
    const long x = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE)
        throw UsageError(command_ + ": " + name + " expects an integer, got '" + v + "'");
    return x;
}

double parseDistance(const std::string& text, const std::string& what) {
    if (text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
        throw UsageError(what + " expects millimetres or 'inf', got '" + text + "'");
    return x;
}

}  // namespace lenslab
