#include "algebra/groebner.h"

#include <chrono>

#include "algebra/error.h"
#include "algebra/flint_threads.h"
#include "algebra/groebner/signature_groebner.h"

namespace locus::algebra {
namespace {

using Clock = std::chrono::steady_clock;

GroebnerOptions options_of(const GroebnerRequest& request) {
    GroebnerOptions options;
    options.selection = request.selection;
    options.deadline = request.deadline;
    options.max_basis_size = request.max_basis_size;
    options.progress = request.progress;
    options.certify = request.certify;
    options.threads = request.threads;
    return options;
}

Algorithm algorithm_of(GroebnerAlgorithm used) {
    switch (used) {
    case GroebnerAlgorithm::buchberger:
        return Algorithm::buchberger;
    case GroebnerAlgorithm::signature:
        return Algorithm::signature;
    case GroebnerAlgorithm::modular:
        return Algorithm::modular;
    }
    return Algorithm::automatic;
}

// The reasons the algorithms over Q leave to their caller (they stop where they poll).
std::string default_reason(GroebnerOutcome outcome) {
    switch (outcome) {
    case GroebnerOutcome::complete:
        return {};
    case GroebnerOutcome::stopped_timeout:
        return "the deadline passed";
    case GroebnerOutcome::stopped_size:
        return "the basis outgrew max_basis_size";
    case GroebnerOutcome::unable:
        return "the algorithm could not answer";
    }
    return {};
}

GroebnerAnswer modulo_prime(std::span<const Polynomial> generators,
                            const GroebnerRequest& request) {
    if (request.algorithm == Algorithm::buchberger || request.algorithm == Algorithm::signature) {
        throw InputError(std::string("algorithm ") + algorithm_name(request.algorithm),
                         "computes over Q, not over GF(" + std::to_string(request.characteristic) +
                             "): use the automatic or the modular algorithm");
    }
    GroebnerAnswer answer;
    answer.characteristic = request.characteristic;
    answer.algorithm = Algorithm::modular;
    answer.certified = false;
    modular::F4Options f4_options;
    f4_options.deadline = request.deadline;
    f4_options.threads = request.threads;
    modular::F4Stats f4_stats;
    const auto start = Clock::now();
    try {
        answer.basis = groebner_modulo(generators, request.characteristic, f4_options, &f4_stats);
    } catch (const Timeout& stop) {
        answer.basis.assign(generators.begin(), generators.end());
        answer.outcome = GroebnerOutcome::stopped_timeout;
        answer.reason = stop.what();
    }
    answer.stats.algorithm = GroebnerAlgorithm::modular;
    answer.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    answer.stats.pairs_created = f4_stats.pairs_created;
    answer.stats.removed_by_product = f4_stats.removed_by_product;
    answer.stats.removed_by_chain = f4_stats.removed_by_chain;
    answer.stats.reductions = f4_stats.pairs_reduced;
    answer.stats.zero_reductions = f4_stats.zero_rows;
    answer.stats.max_basis_size = answer.basis.size();
    answer.f4 = f4_stats;
    return answer;
}

}  // namespace

std::optional<Algorithm> parse_algorithm(std::string_view name) {
    if (name == "auto" || name == "automatic") {
        return Algorithm::automatic;
    }
    if (name == "buchberger") {
        return Algorithm::buchberger;
    }
    if (name == "signature") {
        return Algorithm::signature;
    }
    if (name == "modular" || name == "f4") {
        return Algorithm::modular;
    }
    return std::nullopt;
}

const char* algorithm_name(Algorithm algorithm) {
    switch (algorithm) {
    case Algorithm::automatic:
        return "auto";
    case Algorithm::buchberger:
        return "buchberger";
    case Algorithm::signature:
        return "signature";
    case Algorithm::modular:
        return "modular";
    }
    return "?";
}

GroebnerAnswer groebner(std::span<const Polynomial> generators, const GroebnerRequest& request) {
    release_flint_caches_at_thread_exit();
    if (request.characteristic != 0) {
        return modulo_prime(generators, request);
    }
    const GroebnerOptions options = options_of(request);
    GroebnerResult result;
    ModularStats modular_stats;
    bool used_modular = false;
    switch (request.algorithm) {
    case Algorithm::automatic:
        result = groebner_automatic(generators, options, &modular_stats, &used_modular);
        break;
    case Algorithm::buchberger:
        result = buchberger(generators, options);
        break;
    case Algorithm::signature:
        result = signature_groebner(generators, options);
        break;
    case Algorithm::modular: {
        ModularOptions modular_options;
        modular_options.deadline = request.deadline;
        modular_options.certify = request.certify;
        modular_options.threads = request.threads;
        modular_options.progress = request.progress;
        result = modular_groebner(generators, modular_options, &modular_stats);
        used_modular = true;
        break;
    }
    }
    GroebnerAnswer answer;
    answer.basis = std::move(result.basis);
    answer.outcome = result.outcome;
    answer.reason = result.reason.empty() ? default_reason(result.outcome) : result.reason;
    answer.stats = result.stats;
    answer.algorithm = algorithm_of(result.stats.algorithm);
    if (used_modular) {
        answer.certified = modular_stats.certified;
        answer.modular = modular_stats;
    } else {
        answer.certified = answer.outcome == GroebnerOutcome::complete;
    }
    return answer;
}

}  // namespace locus::algebra
