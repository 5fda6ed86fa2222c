#include "cli/choices.h"

#include <exception>

#include "render/trace_method.h"

namespace locus::cli {

CLI::Validator one_of(const std::vector<Choice>& choices) {
    std::vector<std::string> names;
    std::string expected;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        names.push_back(choices[i].name);
        expected += i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ";
        expected += choices[i].name;
    }
    return CLI::Validator(
        [names, expected](std::string& text) -> std::string {
            for (const std::string& name : names) {
                if (text == name) {
                    return {};
                }
            }
            return "'" + text + "': expected " + expected;
        },
        "");
}

CLI::Validator integer_range(long low, long high, const std::string& expected) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            std::size_t used = 0;
            long value = 0;
            try {
                value = std::stol(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used == 0 || used != text.size() || value < low || value > high) {
                return "'" + text + "': expected " + expected;
            }
            return {};
        },
        "");
}

std::string choice_help(const std::vector<Choice>& choices, const std::string& what) {
    std::string help = what + ": ";
    for (std::size_t i = 0; i < choices.size(); ++i) {
        help += i == 0 ? "" : " | ";
        help += choices[i].name;
        if (!choices[i].help.empty()) {
            help += " (" + choices[i].help + ")";
        }
    }
    return help;
}

const std::vector<Choice>& output_format_choices() {
    static const std::vector<Choice> choices = {
        {"normalized", "the default: one polynomial a line"},
        {"singular", "a ring and an ideal to paste into Singular"},
        {"macaulay2", "the same for Macaulay2"},
        {"latex", "one polynomial a line, in LaTeX"},
        {"msolve", "msolve's input format: variables, characteristic, polynomials"},
        {"sympy", "Python: SymPy symbols and a list of expressions"},
        {"maple", "a Maple list"},
        {"mathematica", "a Mathematica list"},
    };
    return choices;
}

const std::vector<Choice>& trace_method_choices() {
    static const std::vector<Choice> choices = [] {
        std::vector<Choice> table;
        for (const render::TraceMethod method : render::all_trace_methods()) {
            table.push_back({std::string(render::to_string(method)),
                             method == render::TraceMethod::certified ? "the default" : ""});
        }
        return table;
    }();
    return choices;
}

const std::vector<Choice>& on_off_choices() {
    static const std::vector<Choice> choices = {{"on", ""}, {"off", ""}};
    return choices;
}

}  // namespace locus::cli
