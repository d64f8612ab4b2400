#pragma once
// The SH exponentiation methods, selectable by name (--exp-method).
#include <array>
#include <string>
#include <string_view>

namespace ts::sh {

enum class ExpMethod {
    taylor,            // truncated Taylor series of exp in the SH product (baseline)
    dc_isolation,      // exp(DC) as a scalar, Taylor series on the rest [Ren et al. 2006]
    optimal_linear,    // exp(DC) * (a(m) 1 + b(m) f_hat), m = |f_hat|, fitted a, b [Ren et al. 2006]
    scaling_squaring,  // exp(f) = exp(f / 2^k)^(2^k): Taylor on the small vector, k SH squarings
    hybrid,            // DC isolation + optimal linear, + scaling and squaring when m is large
};

inline constexpr std::array<ExpMethod, 5> kAllExpMethods = {ExpMethod::taylor, ExpMethod::dc_isolation,
                                                            ExpMethod::optimal_linear, ExpMethod::scaling_squaring,
                                                            ExpMethod::hybrid};

std::string_view to_string(ExpMethod m);
// Throws ts::InputError naming the valid choices.
ExpMethod parse_exp_method(std::string_view name);
// "taylor|dc_isolation|..." for --help texts.
std::string exp_method_choices();

}  // namespace ts::sh
