// Option values checked while the command line is parsed, in one message form:
//   --method: 'magic': expected auto, groebner, resultant or interpolate
//   --size: '0': expected N from 1 to 4096 (N×N rays)
// An option whose value is one name of a fixed list (an enum on the command line) is declared
// from one table of names and their help, from which both the help text and the check come.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace locus::cli {

struct Choice {
    std::string name;
    std::string help;  // shown in brackets after the name; may be empty
};

// Accepts only the table's names.
CLI::Validator one_of(const std::vector<Choice>& choices);
// Accepts a whole number in [low, high].
CLI::Validator integer_range(long low, long high, const std::string& expected);

// "what: a (help) | b | c".
std::string choice_help(const std::vector<Choice>& choices, const std::string& what);

// Adds `flags` taking one of the choices (a string, or a list of them), with choice_help.
template <class Value>
CLI::Option* add_choice(CLI::App* command, const std::string& flags, Value& value,
                        const std::vector<Choice>& choices, const std::string& what) {
    return command->add_option(flags, value, choice_help(choices, what))->check(one_of(choices));
}

// The tables of the enums several commands share.
const std::vector<Choice>& output_format_choices();  // --format
const std::vector<Choice>& trace_method_choices();   // --method of render and trace
const std::vector<Choice>& on_off_choices();         // --shadows, --ao

}  // namespace locus::cli
