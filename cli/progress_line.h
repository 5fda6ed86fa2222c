// The one line of progress a command may draw on standard error while it works, redrawn in
// place and cleared before anything else is printed there. It draws only when standard error
// is a terminal: in pipes, files and tests it does nothing.
#pragma once

#include <atomic>
#include <cstdio>
#include <functional>
#include <string>

#include "algebra/groebner/buchberger.h"

namespace locus::cli {

class ProgressLine {
  public:
    explicit ProgressLine(std::FILE* out = stderr);
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // A callback for Gröbner-basis work ("label: 120 pairs done, 40 left, basis 31, sugar 7";
    // the modular route: "label: modular, 12 primes, …", "label: certification, 300 of 912
    // S-pairs …"), redrawn at most ten times a second; empty when not on a terminal.
    std::function<void(const algebra::GroebnerProgress&)> groebner(const std::string& label);
    // A callback for work measured as a finished fraction ("label [####    ]  50%"); each call
    // draws (the caller throttles); empty when not on a terminal.
    std::function<void(double)> fraction(const std::string& label);
    // Clears the line if anything was drawn.
    void clear();

  private:
    std::FILE* out_;
    bool terminal_;
    std::atomic<bool> shown_{false};
};

}  // namespace locus::cli
