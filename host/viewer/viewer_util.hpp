// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small helpers the viewer's parts share. Private to fgr_viewer.

#include <fmt/format.h>

#include <ctime>
#include <string>

#include "render/precision.hpp"
#include "scene/formulas/formulas.hpp"

namespace fgr::viewer {

// The precision an image was rendered in, and why when auto chose double.
inline const char* precision_label(Precision choice, bool in_double) {
    if (!in_double) return "float";
    return choice == Precision::Auto ? "double (deep zoom)" : "double";
}

// The local time as "20240131-235959", for the names of screenshots and saved paths.
inline std::string file_timestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
    return text;
}

// "mandelbulb x2, amazing_box": a formula scene's sequence as logs and tooltips show it.
inline std::string sequence_text(const FormulaScene& formula) {
    std::string text;
    for (const FormulaSlot& slot : formula.sequence) {
        if (!text.empty()) text += ", ";
        text += slot.formula->name;
        if (slot.repeat > 1) text += fmt::format(" x{}", slot.repeat);
    }
    return text;
}

}  // namespace fgr::viewer
