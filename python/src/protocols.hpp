// One init function per protocol submodule (buwizz3.cpp, navbot.cpp, osp.cpp).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include <robowire/core/fields.hpp>

namespace rwpy {
void init_buwizz3(pybind11::module_& m);
void init_navbot(pybind11::module_& m);
void init_osp(pybind11::module_& m);

// "1 byte", "13 or 17 bytes", "54 or 68-129 bytes": the input lengths M's decoder accepts.
template <class M>
std::string lengths_text() {
    constexpr auto& runs = robowire::detail::length_runs_v<M>;
    std::string s;
    for (std::size_t i = 0; i < runs.count; ++i) {
        if (i) s += i + 1 == runs.count ? " or " : ", ";
        s += std::to_string(runs.run[i][0]);
        if (runs.run[i][1] != runs.run[i][0]) s += "-" + std::to_string(runs.run[i][1]);
    }
    const bool one = runs.count == 1 && runs.run[0][0] == 1 && runs.run[0][1] == 1;
    return s + (one ? " byte" : " bytes");
}
}  // namespace rwpy
