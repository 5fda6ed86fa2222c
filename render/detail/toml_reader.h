// Reading TOML scene files with errors that name the key (as a dotted path) and its line and
// column: shared by the scene reader (render/scene_file.cpp) and the SDF node reader
// (render/sdf/node_reader.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "algebra/error.h"
#include "render/vec3.h"

namespace locus::render::detail {

inline std::string position(const toml::node& node) {
    const toml::source_position begin = node.source().begin;
    return "line " + std::to_string(begin.line) + ", column " + std::to_string(begin.column);
}

inline std::string describe(const toml::node& node) {
    std::ostringstream out;
    switch (node.type()) {
    case toml::node_type::string:
        out << '"' << node.as_string()->get() << '"';
        break;
    case toml::node_type::table:
        out << "a table";
        break;
    case toml::node_type::array:
        out << "an array of " << node.as_array()->size();
        break;
    default:
        node.visit([&](const auto& value) { out << value; });
    }
    return out.str();
}

// The integer a node holds; nothing when it holds anything else. Not node.value<int64_t>(),
// which converts a float such as 3e21 by an overflowing cast (undefined behaviour; a fuzzer's
// finding).
inline std::optional<std::int64_t> integer_of(const toml::node& node) {
    if (const toml::value<std::int64_t>* integer = node.as_integer()) {
        return integer->get();
    }
    return std::nullopt;
}

// Reads one TOML table, remembering which keys were used so that the rest can be reported.
class TableReader {
  public:
    TableReader(const toml::table& table, std::string path)
        : table_(table), path_(std::move(path)) {}

    // The dotted path of the table's keys ("surface[1].material.").
    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const toml::node& node, const std::string& key,
                           const std::string& expected) const {
        throw InputError(position(node) + ": " + path_ + key,
                         "expected " + expected + ", found " + describe(node));
    }

    const toml::node* find(const std::string& key) {
        used_.insert(key);
        return table_.get(key);
    }

    double number(const std::string& key, double fallback, bool positive = false) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return fallback;
        }
        std::optional<double> value = node->value<double>();
        if (!value || !std::isfinite(*value) || (positive && !(*value > 0.0))) {
            fail(*node, key, positive ? "a positive number" : "a number");
        }
        return *value;
    }

    double non_negative(const std::string& key, double fallback) {
        const toml::node* node = find(key);
        const double value = number(key, fallback);
        if (node != nullptr && value < 0.0) {
            fail(*node, key, "a number ≥ 0");
        }
        return value;
    }

    int count(const std::string& key, int fallback, int low, int high) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return fallback;
        }
        const std::optional<std::int64_t> value = integer_of(*node);
        if (!value || *value < low || *value > high) {
            fail(*node, key,
                 "an integer from " + std::to_string(low) + " to " + std::to_string(high));
        }
        return static_cast<int>(*value);
    }

    bool flag(const std::string& key, bool fallback) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return fallback;
        }
        if (!node->is_boolean()) {
            fail(*node, key, "true or false");
        }
        return *node->value<bool>();
    }

    std::optional<std::string> text(const std::string& key) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return std::nullopt;
        }
        if (!node->is_string()) {
            fail(*node, key, "a string");
        }
        return std::string(*node->value<std::string_view>());
    }

    Vec3 vector(const std::string& key, Vec3 fallback) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return fallback;
        }
        const toml::array* array = node->as_array();
        if (array == nullptr || array->size() != 3) {
            fail(*node, key, "an array of three numbers");
        }
        Vec3 v;
        for (int i = 0; i < 3; ++i) {
            const toml::node& element = (*array)[static_cast<std::size_t>(i)];
            const std::optional<double> value = element.value<double>();
            if (!value || !std::isfinite(*value)) {
                fail(element, key, "an array of three finite numbers");
            }
            v[i] = *value;
        }
        return v;
    }

    const toml::table* subtable(const std::string& key) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return nullptr;
        }
        if (!node->is_table()) {
            fail(*node, key, "a table");
        }
        return node->as_table();
    }

    const toml::array* array_of_tables(const std::string& key) {
        const toml::node* node = find(key);
        if (node == nullptr) {
            return nullptr;
        }
        if (!node->is_array_of_tables()) {
            fail(*node, key, "an array of tables ([[" + key + "]])");
        }
        return node->as_array();
    }

    // Rejects every key that was not asked for.
    void finish() const {
        for (const auto& [key, node] : table_) {
            const std::string name(key.str());
            if (!used_.contains(name)) {
                const toml::source_position begin = key.source().begin;
                throw InputError("line " + std::to_string(begin.line) + ", column " +
                                     std::to_string(begin.column) + ": " + path_ + name,
                                 "unknown key");
            }
        }
    }

  private:
    const toml::table& table_;
    std::string path_;
    std::set<std::string> used_;
};

}  // namespace locus::render::detail
