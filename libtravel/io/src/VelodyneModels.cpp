// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
#include "travel/io/VelodyneModels.hpp"

#include <cctype>

namespace travel::io {

std::string normalisedModel(const std::string& model) {
    std::string s;
    for (char c : model)
        if (std::isalnum(static_cast<unsigned char>(c)))
            s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::optional<VelodyneModel> velodyneModelFor(const std::string& model, std::size_t rows) {
    const std::string m = normalisedModel(model);
    const VelodyneModel vlp16{"VLP16", 2.304 / 55.296}, hdl32{"HDL32", 1.152 / 46.08},
        hdl64{"HDL64", 0.0};
    if (m.rfind("VLP16", 0) == 0 || m.rfind("PUCK", 0) == 0) return vlp16;
    if (m.rfind("HDL32", 0) == 0) return hdl32;
    if (m.rfind("HDL64", 0) == 0) return hdl64;
    if (rows == 16) return vlp16;
    if (rows == 32) return hdl32;
    return std::nullopt;
}

}  // namespace travel::io
