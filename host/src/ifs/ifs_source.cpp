// TEMPORARY: replaced by the kernel source generator (the IFS ray tracer's branch). Until then an
// IFS scene's kernel draws its bounding sphere as a distance-estimated ball, so the scene builds,
// lists and renders end to end.
#include "ifs_source.hpp"

#include <fmt/format.h>

namespace fgr {

std::string ifs_kernel_source(const IfsScene& ifs) {
    const glm::dvec3& c = ifs.bounds.centre;
    return fmt::format(
        "/* TEMPORARY placeholder for '{}': the bounding sphere of its {} maps */\n"
        "inline real scene_de(vec3 p, PARAMS) {{\n"
        "    (void)fgr_params;\n"
        "    return v3_length(v3_sub(p, v3_splat({:#.9g}f, {:#.9g}f, {:#.9g}f))) - {:#.9g}f;\n"
        "}}\n",
        ifs.id, ifs.maps.size(), c.x, c.y, c.z, ifs.bounds.radius);
}

}  // namespace fgr
