// From a page's request to a frame: the surface (the startup scene, or an equation whose names
// other than x, y, z are parameters with the page's values), the camera, the method, colours
// and light, all validated against the limits. Equations are compiled and their clip regions
// fitted once per text and values (a small cache); the default camera is that of the text's
// first values, so that moving a slider keeps the view while the clip follows the surface.
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "algebra/compiled.h"
#include "render/scene.h"
#include "view/view_server.h"

namespace locus::view {

// A request's fields by name (form-encoded), as cpp-httplib gives them.
using Fields = std::multimap<std::string, std::string>;

// A refusal with the field it concerns and, for equations, the position in it.
struct RequestError {
    std::string message;
    std::string field;
    std::size_t line = 0, column = 0;
};

// The names other than x, y, z in `equation`, in order of appearance; throws ParseError (with
// its column) when it is not a polynomial in them.
std::vector<std::string> equation_parameters(const std::string& equation);

struct Frame {
    render::Scene scene;
    std::vector<algebra::CompiledPolynomial> compiled;
    render::CameraSpec camera;
};

class FrameBuilder {
  public:
    FrameBuilder(const ViewOptions& options) : options_(options) {}

    // The frame the fields ask for; RequestError for bad fields (throws it), ParseError and
    // InputError from the equation.
    Frame build(const Fields& fields);

  private:
    struct Compiled {
        algebra::CompiledPolynomial polynomial;
    };
    struct Framing {
        render::ClipRegion clip;
        bool fitted = false;
        render::CameraSpec camera;
    };
    algebra::CompiledPolynomial compiled_equation(const std::string& equation,
                                                  const std::string& values);
    Framing framing_of(const std::string& key, const algebra::CompiledPolynomial& f);

    const ViewOptions& options_;
    std::mutex mutex_;
    std::map<std::string, algebra::CompiledPolynomial> compiled_;  // by equation + values
    std::map<std::string, Framing> framing_;             // clip regions by equation + values
    std::map<std::string, render::CameraSpec> cameras_;  // by equation: its first framing
};

// The field's value, or nothing.
std::optional<std::string> field(const Fields& fields, const std::string& name);

}  // namespace locus::view
