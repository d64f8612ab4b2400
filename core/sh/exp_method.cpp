#include "core/sh/exp_method.hpp"

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::sh {

std::string_view to_string(ExpMethod m) {
    switch (m) {
        case ExpMethod::taylor:
            return "taylor";
        case ExpMethod::dc_isolation:
            return "dc_isolation";
        case ExpMethod::optimal_linear:
            return "optimal_linear";
        case ExpMethod::scaling_squaring:
            return "scaling_squaring";
        case ExpMethod::hybrid:
            return "hybrid";
    }
    return "?";
}

ExpMethod parse_exp_method(std::string_view name) {
    for (ExpMethod m : kAllExpMethods)
        if (to_string(m) == name) return m;
    throw QuantityError(Quantity::exp_method, "", "unknown method '" + std::string(name) + "' (choose " + exp_method_choices() + ")");
}

std::string exp_method_choices() {
    std::string s;
    for (ExpMethod m : kAllExpMethods) {
        if (!s.empty()) s += '|';
        s += to_string(m);
    }
    return s;
}

}  // namespace ts::sh
