// Typed errors thrown by the locus libraries. Library code never exits; only cli/ maps these to
// exit codes (2 input, 3 timeout). Each message is one line meant for a human.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace locus {

class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Malformed text: `line` and `column` are 1-based and point at the offending character.
class ParseError : public Error {
  public:
    ParseError(std::size_t line, std::size_t column, std::string expected, std::string found)
        : Error("line " + std::to_string(line) + ", column " + std::to_string(column) +
                ": expected " + expected + ", found " + found),
          line_(line),
          column_(column),
          expected_(std::move(expected)),
          found_(std::move(found)) {}
    std::size_t line() const { return line_; }
    std::size_t column() const { return column_; }
    const std::string& expected() const { return expected_; }
    const std::string& found() const { return found_; }

  private:
    std::size_t line_, column_;
    std::string expected_, found_;
};

// Well-formed but unacceptable input: an unknown order name, a singular weight matrix, ...
class InputError : public Error {
  public:
    InputError(std::string what_or_where, std::string reason)
        : Error(what_or_where + ": " + reason),
          subject_(std::move(what_or_where)),
          reason_(std::move(reason)) {}
    const std::string& subject() const { return subject_; }
    const std::string& reason() const { return reason_; }

  private:
    std::string subject_, reason_;
};

// An exponent (or a weighted degree) left the packed range; never silently wrapped.
class ExponentOverflow : public Error {
  public:
    explicit ExponentOverflow(const std::string& where) : Error("exponent overflow: " + where) {}
};

// A binary operation on polynomials of different rings.
class MixedRings : public Error {
  public:
    MixedRings() : Error("operands belong to different polynomial rings") {}
};

// A documented size limit would be exceeded (a power with too many terms, an input too large):
// refused before the work, not discovered by running out of memory.
class ResourceLimit : public Error {
  public:
    explicit ResourceLimit(const std::string& what) : Error(what) {}
};

// A deadline passed; thrown only by operations that cannot return a partial result.
class Timeout : public Error {
  public:
    explicit Timeout(const std::string& what) : Error("timeout: " + what) {}
};

// The caller cancelled the work (a newer request replaced it); nothing is wrong with the input.
class Cancelled : public Error {
  public:
    explicit Cancelled(const std::string& what) : Error("cancelled: " + what) {}
};

}  // namespace locus
