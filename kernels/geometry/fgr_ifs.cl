// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: exact ray tracing of IFS scenes (geometry kind "ifs").
 *
 * An IFS scene is the attractor of affine maps w_i(x) = A_i x + b_i. A ball B with w_i(B) inside
 * B for every map (host/scene/ifs/ifs_file.cpp) contains the attractor, and so does every node of
 * the tree of its images w_i1(w_i2(... w_ik(B))), the node's "ellipsoid". A ray is intersected
 * with that tree as Hart and DeFanti describe ("Efficient Antialiased Rendering of 3-D Linear
 * Fractals", SIGGRAPH 1991): nodes wait in a min-heap ordered by the distance at which the ray
 * enters them; the nearest is taken out and its children tested and pushed, and the first leaf to
 * come out is the nearest hit (every node still waiting is entered further away, and holds its
 * descendants). A node is a leaf at the depth slider (`ifs_depth`) or when its world size falls
 * below the pixel's footprint at its distance: detail is resolved as finely as the pixel shows.
 *
 * Each node carries the map from world space into its own space (x -> L x + l), in which it is
 * the ball B itself, so every test is a ray against one ball: the ray o + t d becomes
 * (L o + l) + t (L d), with the same t (affine maps keep ray parameters), so entry distances
 * compare across nodes without going back to world space. The sphere test compares squared
 * quantities and takes a square root only for rays that do meet the ball.
 *
 * The generated scene source (host/scene/ifs/ifs_source.cpp) defines FGR_GEOMETRY_IFS and the
 * tables read here: FGR_IFS_MAPS maps; fgr_ifs_inverse[i] (A_i^-1 row-major, then -A_i^-1 b_i)
 * and fgr_ifs_forward[i] (A_i row-major, then b_i); fgr_ifs_contraction[i] (A_i's largest singular
 * value); fgr_ifs_colour[i]; FGR_IFS_CENTRE_X/Y/Z and FGR_IFS_RADIUS (the ball B).
 *
 * Rays are traced one lane at a time: a heap per lane would not fit beside the others, and the
 * traversal's branches differ per ray. */
#ifdef FGR_GEOMETRY_IFS

typedef FGR_LANES(float, double) ifs_real;
typedef FGR_LANES(float3, double3) ifs_real3;

/* FGR_IFS_HEAP (from the host, kIfsHeapCapacity): nodes a heap holds; a ray whose heap would
 * overflow is traced again depth first (exact, slower) and counted in the stats. */
/* FGR_IFS_NORMAL_LEVELS (from the host, kIfsNormalLevels): the deepest levels whose ellipsoid
 * normals are averaged into the surface normal. */
/* Nodes a ray may visit per march step of the `max_steps` budget: far more than any sensible
 * view needs (the traversal always ends); the cap only keeps a pathological one from stalling
 * the device. */
#define FGR_IFS_NODES_PER_STEP 256
/* Bits per map index in a node's record of its last maps (FGR_IFS_MAPS <= 64). */
#define FGR_IFS_INDEX_BITS 6u
#if FGR_IFS_NORMAL_LEVELS > 10
#error "a node records its last 10 maps (6 bits each in a ulong): FGR_IFS_NORMAL_LEVELS <= 10"
#endif

/* The map from world space into a node's space: rows of L, then l. */
typedef struct ifs_frame {
    ifs_real3 row0, row1, row2, offset;
} ifs_frame;

typedef struct ifs_node {
    ifs_frame frame;
    ifs_real entry; /* where the ray enters the node's ellipsoid (may be < 0: it starts inside) */
    ifs_real size;  /* an upper bound of the ellipsoid's radius in world units */
    int depth;
    int top;      /* the first map on the path from the root (-1 at the root): the colour */
    ulong recent; /* the last maps applied, newest in the low bits (10 of them) */
    int resolved; /* a leaf whose entry is where the ray meets its shape: the hit itself */
} ifs_node;

/* What one lane's trace found. */
typedef struct ifs_hit {
    ifs_real t;
    int hit;
    int visited;   /* nodes taken out of the heap or stack */
    int heap_peak; /* most nodes the heap held (-1: it would have overflowed; traced depth first) */
    ifs_node leaf;
} ifs_hit;

inline ifs_real3 ifs_apply(ifs_frame f, ifs_real3 p) {
    return (ifs_real3)(dot(f.row0, p), dot(f.row1, p), dot(f.row2, p)) + f.offset;
}

inline ifs_real3 ifs_linear(ifs_frame f, ifs_real3 v) {
    return (ifs_real3)(dot(f.row0, v), dot(f.row1, v), dot(f.row2, v));
}

inline ifs_real3 ifs_table_row(__constant const ifs_real* m, int row) {
    return (ifs_real3)(m[3 * row], m[3 * row + 1], m[3 * row + 2]);
}

/* The frame f followed by the affine map m (a table entry: the rows of A, then b): x -> A (L x +
 * l) + b. A child's frame is its map's inverse after its parent's; a parent's, its last map after
 * the child's. */
inline ifs_frame ifs_then(ifs_frame f, __constant const ifs_real* m) {
    const ifs_real3 r0 = ifs_table_row(m, 0), r1 = ifs_table_row(m, 1), r2 = ifs_table_row(m, 2);
    const ifs_real3 c0 = (ifs_real3)(f.row0.x, f.row1.x, f.row2.x);
    const ifs_real3 c1 = (ifs_real3)(f.row0.y, f.row1.y, f.row2.y);
    const ifs_real3 c2 = (ifs_real3)(f.row0.z, f.row1.z, f.row2.z);
    ifs_frame then;
    then.row0 = (ifs_real3)(dot(r0, c0), dot(r0, c1), dot(r0, c2));
    then.row1 = (ifs_real3)(dot(r1, c0), dot(r1, c1), dot(r1, c2));
    then.row2 = (ifs_real3)(dot(r2, c0), dot(r2, c1), dot(r2, c2));
    then.offset =
        (ifs_real3)(dot(r0, f.offset), dot(r1, f.offset), dot(r2, f.offset)) + ifs_table_row(m, 3);
    return then;
}

/* A gradient n taken in a frame's space, in world space: L^T n (the chain rule through
 * x -> L x + l). */
inline ifs_real3 ifs_world_normal(ifs_frame f, ifs_real3 n) {
    return (ifs_real3)(f.row0.x * n.x + f.row1.x * n.y + f.row2.x * n.z,
                       f.row0.y * n.x + f.row1.y * n.y + f.row2.y * n.z,
                       f.row0.z * n.x + f.row1.z * n.y + f.row2.z * n.z);
}

/* Where the ray o + t d enters and leaves the ball B seen in frame f, if it meets it:
 * |L o + l - c + t L d|^2 = R^2, with oc = L o + l - c and dl = L d. As the seed does, the test
 * itself needs no division and no square root (they wait for rays that do meet the ball): the
 * centre's squared distance from the ray times |dl|^2 is |oc x dl|^2 (Lagrange's identity), and
 * the ray misses where that exceeds R^2 |dl|^2. The cross product also keeps the precision that
 * the textbook discriminant b^2 - ac loses for a small node seen from afar, where both terms grow
 * with the node's depth and cancel (Ray Tracing Gems, "Precision Improvements for Ray/Sphere
 * Intersection", Haines et al. 2019: 6% depth errors in float at depth 6 before, 1e-6 after). */
inline int ifs_enter(ifs_frame f, ifs_real3 o, ifs_real3 d, ifs_real* entry, ifs_real* exit) {
    const ifs_real3 centre = (ifs_real3)(FGR_IFS_CENTRE_X, FGR_IFS_CENTRE_Y, FGR_IFS_CENTRE_Z);
    const ifs_real radius2 = (ifs_real)(FGR_IFS_RADIUS * FGR_IFS_RADIUS);
    const ifs_real3 oc = ifs_apply(f, o) - centre;
    const ifs_real3 dl = ifs_linear(f, d);
    const ifs_real a = dot(dl, dl);
    const ifs_real3 across = cross(oc, dl);
    const ifs_real room = radius2 * a - dot(across, across); /* (R^2 - h^2) |dl|^2 */
    if (!(room >= 0) || !(a > 0)) return 0;
    const ifs_real inverse_a = 1 / a;
    const ifs_real closest = -dot(oc, dl) * inverse_a; /* t of the closest approach */
    const ifs_real half_chord = sqrt(room) * inverse_a;
    *entry = closest - half_chord;
    *exit = closest + half_chord;
    return 1;
}

/* The root node: the ball B in world space. */
inline ifs_node ifs_root(void) {
    ifs_node root;
    root.frame.row0 = (ifs_real3)(1, 0, 0);
    root.frame.row1 = (ifs_real3)(0, 1, 0);
    root.frame.row2 = (ifs_real3)(0, 0, 1);
    root.frame.offset = (ifs_real3)(0, 0, 0);
    root.entry = 0;
    root.size = (ifs_real)FGR_IFS_RADIUS;
    root.depth = 0;
    root.top = -1;
    root.recent = 0ul;
    root.resolved = 0;
    return root;
}

/* Child `map` of a node; its entry distance is set once the ray has been tested against it. */
inline ifs_node ifs_child(ifs_node parent, int map) {
    ifs_node child;
    child.frame = ifs_then(parent.frame, fgr_ifs_inverse[map]);
    child.entry = 0;
    child.size = parent.size * (ifs_real)fgr_ifs_contraction[map];
    child.depth = parent.depth + 1;
    child.top = parent.top < 0 ? map : parent.top;
    child.recent = (parent.recent << FGR_IFS_INDEX_BITS) | (ulong)map;
    child.resolved = 0;
    return child;
}

/* Whether a node is drawn as it is: at the depth cap, or smaller than the pixel's footprint at
 * the distance where the ray enters it (the footprint grows with the whole path, `travelled`
 * before the ray's origin, as the marcher's hit test does). */
inline int ifs_is_leaf(ifs_node node, int max_depth, ifs_real travelled, float footprint) {
    return node.depth >= max_depth ||
           node.size <= (ifs_real)footprint * (fmax(node.entry, (ifs_real)0) + travelled);
}

#if FGR_IFS_LEAF_PLANES > 0
/* Where the ray enters the leaf's polytope (half-spaces n . x <= h in the node's space), and
 * through which plane; 0 where it misses. Plane by plane, as Kay and Kajiya's slabs: a plane the
 * ray crosses inwards (n . d < 0) bounds its entry, one it crosses outwards its exit. */
inline int ifs_polytope_enter(ifs_frame f, ifs_real3 o, ifs_real3 d, ifs_real* entry, int* face) {
    const ifs_real3 ol = ifs_apply(f, o);
    const ifs_real3 dl = ifs_linear(f, d);
    ifs_real enter = -INFINITY, leave = INFINITY;
    *face = 0;
    for (int i = 0; i < FGR_IFS_LEAF_PLANES; ++i) {
        const ifs_real3 n = ifs_table_row(fgr_ifs_leaf_planes[i], 0);
        const ifs_real h = fgr_ifs_leaf_planes[i][3];
        const ifs_real along = dot(n, dl);
        const ifs_real room = h - dot(n, ol); /* >= 0 where the origin is inside this plane */
        if (along == 0) {
            if (room < 0) return 0; /* parallel, outside */
            continue;
        }
        const ifs_real t = room / along;
        if (along < 0) {
            if (t > enter) {
                enter = t;
                *face = i;
            }
        } else {
            leave = fmin(leave, t);
        }
    }
    *entry = enter;
    return enter <= leave;
}
#endif

/* Whether a leaf draws the scene's polytope (FGR_IFS_LEAF_PLANES > 0): at the depth cap, where
 * the image shows the level-n solid exactly. A leaf the footprint stopped is below a pixel and
 * draws its ball, which covers what the pixel sees of the attractor inside it, as the marcher's
 * hit footprint does (tiny exact polytopes there would alias into speckle). */
inline int ifs_draws_polytope(ifs_node node, int max_depth) {
    return FGR_IFS_LEAF_PLANES > 0 && node.depth >= max_depth;
}

/* Where the ray meets what a leaf draws, if it does: its ball's entry (already known), or its
 * polytope's entry, which lies inside the ball. */
inline int ifs_leaf_hit(ifs_node node, ifs_real3 o, ifs_real3 d, int max_depth, ifs_real* t) {
#if FGR_IFS_LEAF_PLANES > 0
    if (ifs_draws_polytope(node, max_depth)) {
        int face;
        return ifs_polytope_enter(node.frame, o, d, t, &face);
    }
#else
    (void)o;
    (void)d;
    (void)max_depth;
#endif
    *t = node.entry;
    return 1;
}

/* Heap of nodes by entry distance, smallest on top (a binary heap in an array). A push raises
 * *peak, the most nodes the heap has held. */
inline void ifs_heap_push(ifs_node* heap, int* count, ifs_node node, int* peak) {
    int i = (*count)++;
    *peak = max(*peak, *count);
    while (i > 0) {
        const int parent = (i - 1) / 2;
        if (heap[parent].entry <= node.entry) break;
        heap[i] = heap[parent];
        i = parent;
    }
    heap[i] = node;
}

inline ifs_node ifs_heap_pop(ifs_node* heap, int* count) {
    const ifs_node top = heap[0];
    const ifs_node last = heap[--(*count)];
    int i = 0;
    for (;;) {
        int child = 2 * i + 1;
        if (child >= *count) break;
        if (child + 1 < *count && heap[child + 1].entry < heap[child].entry) ++child;
        if (last.entry <= heap[child].entry) break;
        heap[i] = heap[child];
        i = child;
    }
    if (*count > 0) heap[i] = last;
    return top;
}

/* Depth first with pruning: the exact fallback when the heap would overflow, and with `any_hit`
 * the shadow rays' test (the first leaf within reach ends it, nothing is sorted). Children are
 * visited in map order; a child entered beyond the nearest leaf found so far is skipped. The
 * stack holds one node per level plus the next child to try there. */
inline ifs_hit ifs_trace_depth_first(ifs_real3 o, ifs_real3 d, ifs_real travelled, ifs_real reach,
                                     float footprint, int max_depth, int max_nodes, int any_hit) {
    ifs_hit result;
    result.hit = 0;
    result.t = reach;
    result.visited = 0;
    result.heap_peak = -1; /* no heap: a ray that overflowed one, or a shadow ray */
    ifs_node stack[FGR_IFS_MAX_DEPTH + 1];
    int next_map[FGR_IFS_MAX_DEPTH + 1];
    ifs_real entry, exit;
    ifs_node root = ifs_root();
    if (!ifs_enter(root.frame, o, d, &entry, &exit) || exit <= 0 || entry > reach) return result;
    root.entry = entry;
    int level = 0;
    stack[0] = root;
    next_map[0] = 0;
    result.visited = 1;
    if (ifs_is_leaf(root, max_depth, travelled, footprint)) {
        ifs_real t;
        if (ifs_leaf_hit(root, o, d, max_depth, &t) && t > 0 && t <= reach) {
            result.hit = 1;
            result.t = t;
            result.leaf = root;
        }
        return result;
    }
    while (level >= 0 && result.visited < max_nodes) {
        if (next_map[level] >= FGR_IFS_MAPS) {
            --level;
            continue;
        }
        const int map = next_map[level]++;
        const ifs_node parent = stack[level];
        ifs_node child = ifs_child(parent, map);
        if (!ifs_enter(child.frame, o, d, &entry, &exit) || exit <= 0 || entry > result.t) {
            continue;
        }
        child.entry = entry;
        ++result.visited;
        if (ifs_is_leaf(child, max_depth, travelled, footprint)) {
            ifs_real t;
            if (ifs_leaf_hit(child, o, d, max_depth, &t) && t > 0 && t <= result.t &&
                (!result.hit || t < result.t)) {
                result.hit = 1;
                result.t = t;
                result.leaf = child;
                if (any_hit) return result;
            }
            continue;
        }
        ++level;
        stack[level] = child;
        next_map[level] = 0;
    }
    return result;
}

/* A ray whose heap is full, traced again depth first (which needs no heap), counting the
 * `visited` nodes the heap had taken already. */
inline ifs_hit ifs_retrace_depth_first(ifs_real3 o, ifs_real3 d, ifs_real travelled, ifs_real reach,
                                       float footprint, int max_depth, int max_nodes, int visited) {
    ifs_hit exact =
        ifs_trace_depth_first(o, d, travelled, reach, footprint, max_depth, max_nodes, 0);
    exact.visited += visited;
    return exact;
}

/* The nearest hit, best first (see the top of this file). */
inline ifs_hit ifs_trace_nearest(ifs_real3 o, ifs_real3 d, ifs_real travelled, ifs_real reach,
                                 float footprint, int max_depth, int max_nodes) {
    ifs_hit result;
    result.hit = 0;
    result.t = reach;
    result.visited = 0;
    result.heap_peak = 0;
    ifs_node heap[FGR_IFS_HEAP];
    int count = 0;
    ifs_real entry, exit;
    ifs_node root = ifs_root();
    if (!ifs_enter(root.frame, o, d, &entry, &exit) || exit <= 0 || entry > reach) return result;
    root.entry = entry;
    ifs_heap_push(heap, &count, root, &result.heap_peak);
    while (count > 0 && result.visited < max_nodes) {
        ifs_node node = ifs_heap_pop(heap, &count);
        ++result.visited;
        if (node.resolved) {
            /* Every node still waiting is entered at or after this hit: the nearest. */
            result.hit = 1;
            result.t = node.entry;
            result.leaf = node;
            return result;
        }
        if (ifs_is_leaf(node, max_depth, travelled, footprint)) {
            /* A leaf whose shape the ray meets ahead of its origin (not the surface a ray
             * starts inside) goes back into the heap at that distance: a ball's at once (it is
             * the entry it was taken out at), a polytope's deeper inside the ball, where nodes
             * entered before it may still hold a nearer hit. */
            ifs_real t;
            if (!ifs_leaf_hit(node, o, d, max_depth, &t) || !(t > 0) || t > reach) continue;
            node.entry = t;
            node.resolved = 1;
            if (!ifs_draws_polytope(node, max_depth) || count == 0 || t <= heap[0].entry) {
                result.hit = 1;
                result.t = t;
                result.leaf = node;
                return result;
            }
            if (count == FGR_IFS_HEAP) {
                return ifs_retrace_depth_first(o, d, travelled, reach, footprint, max_depth,
                                               max_nodes, result.visited);
            }
            ifs_heap_push(heap, &count, node, &result.heap_peak);
            continue;
        }
        for (int map = 0; map < FGR_IFS_MAPS; ++map) {
            ifs_node child = ifs_child(node, map);
            if (!ifs_enter(child.frame, o, d, &entry, &exit) || exit <= 0 || entry > reach) {
                continue;
            }
            child.entry = entry;
            if (count == FGR_IFS_HEAP) {
                return ifs_retrace_depth_first(o, d, travelled, reach, footprint, max_depth,
                                               max_nodes, result.visited);
            }
            ifs_heap_push(heap, &count, child, &result.heap_peak);
        }
    }
    return result;
}

/* A ball leaf's surface normal: the ellipsoid normals of the leaf and of its ancestors up to
 * FGR_IFS_NORMAL_LEVELS levels, each taken at the hit point and made a unit vector in world
 * space, averaged. A leaf's own ellipsoid is a coarse stand-in for the attractor inside it; its
 * ancestors' normals describe the shape the leaf belongs to. In a node's space the ellipsoid is
 * the ball B, whose normal at q is q - c; in world space the normal is L^T (q - c). Going up a
 * level applies the node's last map after its frame. */
inline ifs_real3 ifs_ball_normal(ifs_node leaf, ifs_real3 hit_point) {
    const ifs_real3 centre = (ifs_real3)(FGR_IFS_CENTRE_X, FGR_IFS_CENTRE_Y, FGR_IFS_CENTRE_Z);
    ifs_frame f = leaf.frame;
    ulong recent = leaf.recent;
    ifs_real3 sum = (ifs_real3)(0, 0, 0);
    const int levels = min(FGR_IFS_NORMAL_LEVELS, leaf.depth + 1);
    for (int level = 0; level < levels; ++level) {
        const ifs_real3 world = ifs_world_normal(f, ifs_apply(f, hit_point) - centre);
        const ifs_real length2 = dot(world, world);
        if (length2 > 0) sum += world * rsqrt(length2);
        if (level + 1 == levels) break;
        const int map = (int)(recent & ((1ul << FGR_IFS_INDEX_BITS) - 1ul));
        recent >>= FGR_IFS_INDEX_BITS;
        f = ifs_then(f, fgr_ifs_forward[map]);
    }
    const ifs_real length2 = dot(sum, sum);
    return length2 > 0 ? sum * rsqrt(length2) : (ifs_real3)(0, 0, 1);
}

/* The surface normal at a leaf hit: the face of the polytope the ray entered through (exact), or
 * for ball leaves the average of ifs_ball_normal. */
inline ifs_real3 ifs_normal(ifs_node leaf, ifs_real3 o, ifs_real3 d, ifs_real t, int max_depth) {
#if FGR_IFS_LEAF_PLANES > 0
    if (!ifs_draws_polytope(leaf, max_depth)) return ifs_ball_normal(leaf, o + t * d);
    ifs_real entry;
    int face;
    ifs_polytope_enter(leaf.frame, o, d, &entry, &face);
    return normalize(ifs_world_normal(leaf.frame, ifs_table_row(fgr_ifs_leaf_planes[face], 0)));
#else
    (void)max_depth;
    return ifs_ball_normal(leaf, o + t * d);
#endif
}

/* The albedo of a leaf: its first map's colour (the root, at depth 0: their mean). */
inline ifs_real3 ifs_colour(ifs_node leaf) {
    if (leaf.top < 0) return (ifs_real3)(FGR_IFS_MEAN_COLOUR);
    return (ifs_real3)(fgr_ifs_colour[leaf.top][0], fgr_ifs_colour[leaf.top][1],
                       fgr_ifs_colour[leaf.top][2]);
}

/* Lanes in and out of private arrays, to trace them one at a time. */
#if FGR_WIDTH == 1
#define fgr_lanes_store(v, a) ((a)[0] = (v))
#define fgr_lanes_load(a) ((a)[0])
#else
#define fgr_lanes_store(v, a) FGR_PASTE(vstore, FGR_WIDTH)((v), 0, (a))
#define fgr_lanes_load(a) FGR_PASTE(vload, FGR_WIDTH)(0, (a))
#endif

/* The marcher's entry point for IFS scenes (fgr_march.cl's march_rays_core): every active lane
 * traced exactly. `departing` rays leave a surface point: the leaf they start in does not stop
 * them (a hit counts only ahead of the origin, so the rule is the same for every ray). `steps`
 * counts the nodes each lane visited; `heap_peak`, the most its heap held. Shadow rays (`any_hit`)
 * take the first leaf within reach. */
march_result ifs_trace_rays(vec3 origin, vec3 dir, mask active, real travelled, real reach,
                            march_limits limits, int any_hit, PARAMS) {
    ifs_real ox[FGR_WIDTH], oy[FGR_WIDTH], oz[FGR_WIDTH], dx[FGR_WIDTH], dy[FGR_WIDTH],
        dz[FGR_WIDTH], travelled_lanes[FGR_WIDTH], reach_lanes[FGR_WIDTH];
    FGR_LANES(int, long) active_lanes[FGR_WIDTH];
    fgr_lanes_store(origin.x, ox);
    fgr_lanes_store(origin.y, oy);
    fgr_lanes_store(origin.z, oz);
    fgr_lanes_store(dir.x, dx);
    fgr_lanes_store(dir.y, dy);
    fgr_lanes_store(dir.z, dz);
    fgr_lanes_store(travelled, travelled_lanes);
    fgr_lanes_store(reach, reach_lanes);
    fgr_lanes_store(active, active_lanes);
    ifs_real t[FGR_WIDTH], nx[FGR_WIDTH], ny[FGR_WIDTH], nz[FGR_WIDTH], cr[FGR_WIDTH],
        cg[FGR_WIDTH], cb[FGR_WIDTH];
    FGR_LANES(int, long) hit[FGR_WIDTH], visited[FGR_WIDTH], peak[FGR_WIDTH], level[FGR_WIDTH];
    const int max_depth = (int)param_ifs_depth;
    const int max_nodes = limits.max_steps * FGR_IFS_NODES_PER_STEP;
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        t[lane] = 0;
        hit[lane] = 0;
        visited[lane] = 0;
        peak[lane] = 0;
        level[lane] = -1;
        nx[lane] = 0;
        ny[lane] = 0;
        nz[lane] = 1;
        cr[lane] = cg[lane] = cb[lane] = 0;
        if (!active_lanes[lane]) continue;
        const ifs_real3 o = (ifs_real3)(ox[lane], oy[lane], oz[lane]);
        const ifs_real3 d = (ifs_real3)(dx[lane], dy[lane], dz[lane]);
        const ifs_hit found =
            any_hit ? ifs_trace_depth_first(o, d, travelled_lanes[lane], reach_lanes[lane],
                                            limits.footprint, max_depth, max_nodes, 1)
                    : ifs_trace_nearest(o, d, travelled_lanes[lane], reach_lanes[lane],
                                        limits.footprint, max_depth, max_nodes);
        visited[lane] = found.visited;
        peak[lane] = any_hit ? 0 : found.heap_peak;
        t[lane] = found.hit ? found.t : reach_lanes[lane];
        if (!found.hit) continue;
        hit[lane] = FGR_WIDTH == 1 ? 1 : -1; /* a true lane, as select() reads it */
        level[lane] = found.leaf.depth;
        if (any_hit) continue;
        const ifs_real3 n = ifs_normal(found.leaf, o, d, found.t, max_depth);
        const ifs_real3 c = ifs_colour(found.leaf);
        nx[lane] = n.x;
        ny[lane] = n.y;
        nz[lane] = n.z;
        cr[lane] = c.x;
        cg[lane] = c.y;
        cb[lane] = c.z;
    }
    march_result result;
    result.t = fgr_lanes_load(t);
    result.hit = fgr_lanes_load(hit);
    result.steps = fgr_lanes_load(visited);
    result.heap_peak = fgr_lanes_load(peak);
    result.leaf_depth = fgr_lanes_load(level);
    result.normal = v3(fgr_lanes_load(nx), fgr_lanes_load(ny), fgr_lanes_load(nz));
    result.albedo = v3(fgr_lanes_load(cr), fgr_lanes_load(cg), fgr_lanes_load(cb));
#ifdef FGR_EFFECT_GLOW
    result.closest = fgr_real(1e20f);
#endif
    return result;
}

#endif
