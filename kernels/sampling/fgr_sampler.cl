// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: sampling, where every render mode's random numbers come from. One hash
 * (lowbias32, sampler_mix) makes them all, in two generators:
 *
 *   - the path tracer's sampler below, an Owen-scrambled Sobol sequence handed out one dimension
 *     at a time;
 *   - hashed numbers for the camera's jitter and lens (sample_camera, at the end) and the brute
 *     mode's strata (fgr_mode_brute.cl): a seed from the pixel and the sample
 *     (sampler_pixel_seed), hashed once for each number wanted (sampler_hashed_unit).
 *
 * They are seeded differently because they want different things. A Sobol sample must take its
 * sample index from the sequence, never from the scramble: the scramble has to be one per pixel
 * and dimension for every sample of the pixel to stay stratified, and it takes the render's seed
 * so that renders with other seeds add up (SampleBudget::seeded). The hashed numbers have no
 * sequence, so the sample's index goes into their seed, and they take no render seed. Both rules
 * are kept as they are because every image fgr renders depends on them bit for bit.
 *
 * A sampler hands a path out its random numbers one dimension at a time (pbrt-v4's
 * Sampler::Get1D/Get2D): the camera takes the first pair (position in the pixel), the lens the
 * next, then each bounce its own. Sample `sample` of a pixel is one point of a padded,
 * Owen-scrambled Sobol sequence (Brent Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4),
 * 2020; pbrt-v4's PaddedSobolSampler):
 *
 *   - every pair of dimensions is the first two Sobol dimensions, a (0,2)-sequence: for any k, the
 *     2^k samples of an aligned block (the first 2^k of a progressive render in particular) put
 *     exactly one point in every elementary interval of area 2^-k, of any shape 2^-a x 2^-b;
 *   - each pair's points are Owen-scrambled (nested uniform scrambling, which keeps those nets)
 *     by a hash seeded from (pixel, dimension, render seed), so pixels and dimensions get
 *     independent random scrambles and the estimate stays unbiased;
 *   - each pair also reads the sequence in its own order: the sample index goes through a nested
 *     uniform scramble of its own, which maps every aligned block of 2^k indices onto an aligned
 *     block of Sobol indices (so nets stay nets) while pairing the pair's points with the other
 *     pairs' points at random. Without it, the pairs of a path would be the same Sobol points
 *     scrambled differently, and strongly correlated.
 *
 * A 1D request takes a dimension slot of its own and uses the first (van der Corput) half of that
 * slot's pair, so 1D and 2D requests can be mixed freely and every dimension is stratified. The
 * sequence is the same at every packet width and precision: all arithmetic is on 32-bit unsigned
 * lanes, and only the final conversion differs (float keeps the top 24 bits, double all 32).
 *
 * Progressive renders call sampler_start with sample 0, 1, 2, ... for each pixel; the best
 * stratification is at power-of-two sample counts.
 *
 * The dimension counter is one for the whole packet, as lane-wise control flow makes every lane
 * take the same calls. For a lane's numbers not to depend on its packet, a path should draw a
 * fixed number of dimensions per bounce (lanes whose path has ended keep drawing and ignore
 * them), never a count that depends on another lane, such as a loop run while any lane rejects
 * its sample. */

/* An unsigned 32-bit integer per lane, in both precisions (`ulanes` is 64 bits in double builds;
 * the sampler wants 32-bit wrap-around). The sampler needs no masks, so it never selects on
 * them. */
typedef FGR_LANE_TYPE(uint) uint_lanes;
#define convert_uint_lanes FGR_LANE_TYPE(convert_uint)

typedef struct real2 {
    real x, y;
} real2;

/* A path's sampler, one per packet: each lane its own pixel. */
typedef struct sampler {
    uint_lanes pixel; /* the hash of (pixel, render seed) that seeds every dimension */
    uint index;       /* the sample index (the same in every lane) */
    uint dimension;   /* the next dimension slot handed out */
} sampler;

/* A well-mixed 32-bit hash (Chris Wellons' lowbias32): every input bit flips each output bit
 * with probability close to 1/2. The one hash of the kernel library's random numbers. */
#define FGR_SAMPLER_MIX(x)  \
    do {                    \
        (x) ^= (x) >> 16;   \
        (x) *= 0x7feb352du; \
        (x) ^= (x) >> 15;   \
        (x) *= 0x846ca68bu; \
        (x) ^= (x) >> 16;   \
    } while (0)

inline uint_lanes sampler_mix(uint_lanes x) {
    FGR_SAMPLER_MIX(x);
    return x;
}

inline uint sampler_mix_uniform(uint x) {
    FGR_SAMPLER_MIX(x);
    return x;
}

/* The seed of the hashed numbers of sample (or pass) `sample` of the pixels (px, py) (integral
 * values >= 0): the coordinates and the sample through Teschner et al.'s spatial hash, in 32-bit
 * lanes at every precision, so float and double renders draw the same numbers. */
inline uint_lanes sampler_pixel_seed(real px, real py, int sample) {
    return convert_uint_lanes(px) * 73856093u ^ convert_uint_lanes(py) * 19349663u ^
           (uint_lanes)((uint)sample * 83492791u);
}

/* A hashed number in [0, 1): the hash's top 24 bits, in both precisions. Unlike sampler_to_real
 * it keeps 24 bits in double too, so a double render's jitter and strata are a float render's. */
inline real sampler_hashed_unit(uint_lanes hashed) {
    return convert_real(hashed >> 8) * (1.0f / 16777216.0f);
}

/* The bits of x in reverse order (bit 0 becomes bit 31). */
#define FGR_SAMPLER_REVERSE(x)                                       \
    do {                                                             \
        (x) = (((x) >> 1) & 0x55555555u) | (((x)&0x55555555u) << 1); \
        (x) = (((x) >> 2) & 0x33333333u) | (((x)&0x33333333u) << 2); \
        (x) = (((x) >> 4) & 0x0f0f0f0fu) | (((x)&0x0f0f0f0fu) << 4); \
        (x) = (((x) >> 8) & 0x00ff00ffu) | (((x)&0x00ff00ffu) << 8); \
        (x) = ((x) >> 16) | ((x) << 16);                             \
    } while (0)

inline uint_lanes sampler_reverse_bits(uint_lanes x) {
    FGR_SAMPLER_REVERSE(x);
    return x;
}

inline uint sampler_reverse_bits_uniform(uint x) {
    FGR_SAMPLER_REVERSE(x);
    return x;
}

/* Owen scrambling of a bit-reversed value (Laine and Karras' permutation, with the constants of
 * Nathan Vegdahl's improved hash, as pbrt-v4's FastOwenScrambler and Cycles use): every step
 * (adding, multiplying by an odd number, x ^= x * even) is a bijection in which a bit depends
 * only on itself and lower bits. Read in the normal order, each digit of the value is flipped by
 * a hash of the digits above it: a nested uniform scramble, seeded by `seed`. */
inline uint_lanes sampler_owen_reversed(uint_lanes x, uint_lanes seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

/* The second Sobol dimension of index i, bit-reversed. Its generator matrix's column j is
 * v_j = v_{j-1} ^ (v_{j-1} >> 1) from v_0 = 2^31 (Pascal's triangle mod 2): read from the top,
 * digit k of the value is the parity of the index bits j with C(j, k) odd, which by Lucas'
 * theorem are the j whose binary digits include k's. That sum over supersets takes one
 * shift-and-xor per bit of k. (The first dimension, van der Corput, is i itself in this
 * reversed form.) */
inline uint_lanes sampler_sobol1_reversed(uint_lanes i) {
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    i ^= (i >> 16) & 0x0000ffffu;
    return i;
}

/* A 32-bit fraction as a real in [0, 1). Float keeps the top 24 bits (exactly representable, so
 * no rounding moves a point across an interval edge, and the largest value is 1 - 2^-24); double
 * keeps all 32, capped (in integers: no float built-in sees the value) at the same largest float
 * below 1, so a double sample stays below 1 when stored as a float. A float sample is therefore
 * the double one truncated, less by under 2^-24. */
inline real sampler_to_real(uint_lanes bits) {
#ifdef FGR_DOUBLE
    return convert_real(min(bits, (uint_lanes)(0xffffff00u))) * (1.0 / 4294967296.0);
#else
    return convert_real(bits >> 8) * (1.0f / 16777216.0f);
#endif
}

/* Starts sample `sample` of the pixels (px, py) (each lane its own; integral values >= 0, as
 * fgr_render.cl computes them) of a render seeded with `seed` (0 by default). */
inline sampler sampler_start(real px, real py, int sample, uint seed) {
    sampler s;
    uint_lanes h = sampler_mix(convert_uint_lanes(py) ^ (uint_lanes)(sampler_mix_uniform(seed)));
    s.pixel = sampler_mix(convert_uint_lanes(px) ^ h);
    s.index = (uint)sample;
    s.dimension = 0u;
    return s;
}

/* The shuffled sample index of the next dimension slot, and its two scrambling seeds. */
inline uint_lanes sampler_next_slot(sampler* s, uint_lanes* seed_x, uint_lanes* seed_y) {
    const uint_lanes slot = sampler_mix(
        s->pixel ^ (uint_lanes)(sampler_mix_uniform(s->dimension * 0x9e3779b9u + 0x632be5abu)));
    s->dimension += 1u;
    const uint_lanes seed_index = sampler_mix(slot ^ 0x1b873593u);
    *seed_x = sampler_mix(slot ^ 0xcc9e2d51u);
    *seed_y = sampler_mix(slot ^ 0xe6546b64u);
    /* Nested uniform scramble of the index: digit j of the result is digit j of the index flipped
     * by a hash of the digits above it, so the first 2^k indices (every aligned block of 2^k) map
     * onto an aligned block of 2^k. */
    const uint_lanes reversed = (uint_lanes)(sampler_reverse_bits_uniform(s->index));
    return sampler_reverse_bits(sampler_owen_reversed(reversed, seed_index));
}

/* The next pair of dimensions: one point of the slot's scrambled (0,2)-sequence. */
inline real2 sampler_next_2d(sampler* s) {
    uint_lanes seed_x, seed_y;
    const uint_lanes index = sampler_next_slot(s, &seed_x, &seed_y);
    real2 u;
    u.x = sampler_to_real(sampler_reverse_bits(sampler_owen_reversed(index, seed_x)));
    u.y = sampler_to_real(
        sampler_reverse_bits(sampler_owen_reversed(sampler_sobol1_reversed(index), seed_y)));
    return u;
}

/* The next dimension, in a slot of its own: its pair's first (van der Corput) half. */
inline real sampler_next_1d(sampler* s) {
    uint_lanes seed_x, seed_y;
    const uint_lanes index = sampler_next_slot(s, &seed_x, &seed_y);
    return sampler_to_real(sampler_reverse_bits(sampler_owen_reversed(index, seed_x)));
}

/* --- The same sequence for a packet whose lanes trace different samples, each at its own
 * dimension: the path tracer's regrouped kernel (fgr_mode_path.cl), where a lane whose path has
 * ended starts another (pixel, sample) at once while its neighbours are still bouncing. A path
 * draws exactly the numbers sampler_start/sampler_next_* give it, whichever lane traces it. */
typedef struct lane_sampler {
    uint_lanes pixel;     /* the hash of (pixel, render seed) that seeds every dimension */
    uint_lanes index;     /* each lane's sample index */
    uint_lanes dimension; /* each lane's next dimension slot */
} lane_sampler;

/* Sample `sample` of the pixels (px, py) of a render seeded with `seed`, per lane. */
inline lane_sampler lane_sampler_start(real px, real py, uint_lanes sample, uint_lanes seed) {
    lane_sampler s;
    const uint_lanes h = sampler_mix(convert_uint_lanes(py) ^ sampler_mix(seed));
    s.pixel = sampler_mix(convert_uint_lanes(px) ^ h);
    s.index = sample;
    s.dimension = (uint_lanes)(0u);
    return s;
}

/* `fresh` where the lanes of `m` hold (a mask: -1 in vector lanes, 1 for scalars), `old`
 * elsewhere: the sampler's lanes are 32 bits even where masks are 64. */
inline uint_lanes lane_sampler_pick(uint_lanes old, uint_lanes fresh, mask m) {
    const uint_lanes bits = (uint_lanes)(0u) - (convert_uint_lanes(m) & 1u);
    return (fresh & bits) | (old & ~bits);
}

/* The lanes of `m` take the state of `fresh`, the others keep theirs. */
inline void lane_sampler_take(lane_sampler* s, lane_sampler fresh, mask m) {
    s->pixel = lane_sampler_pick(s->pixel, fresh.pixel, m);
    s->index = lane_sampler_pick(s->index, fresh.index, m);
    s->dimension = lane_sampler_pick(s->dimension, fresh.dimension, m);
}

/* sampler_next_slot with each lane's own index and dimension; only the lanes of `drawing` move
 * on to their next dimension (the others are at another point of their paths). */
inline uint_lanes lane_sampler_next_slot(lane_sampler* s, mask drawing, uint_lanes* seed_x,
                                         uint_lanes* seed_y) {
    const uint_lanes slot =
        sampler_mix(s->pixel ^ sampler_mix(s->dimension * 0x9e3779b9u + 0x632be5abu));
    s->dimension += convert_uint_lanes(drawing) & 1u;
    const uint_lanes seed_index = sampler_mix(slot ^ 0x1b873593u);
    *seed_x = sampler_mix(slot ^ 0xcc9e2d51u);
    *seed_y = sampler_mix(slot ^ 0xe6546b64u);
    const uint_lanes reversed = sampler_reverse_bits(s->index);
    return sampler_reverse_bits(sampler_owen_reversed(reversed, seed_index));
}

inline real2 lane_sampler_next_2d(lane_sampler* s, mask drawing) {
    uint_lanes seed_x, seed_y;
    const uint_lanes index = lane_sampler_next_slot(s, drawing, &seed_x, &seed_y);
    real2 u;
    u.x = sampler_to_real(sampler_reverse_bits(sampler_owen_reversed(index, seed_x)));
    u.y = sampler_to_real(
        sampler_reverse_bits(sampler_owen_reversed(sampler_sobol1_reversed(index), seed_y)));
    return u;
}

inline real lane_sampler_next_1d(lane_sampler* s, mask drawing) {
    uint_lanes seed_x, seed_y;
    const uint_lanes index = lane_sampler_next_slot(s, drawing, &seed_x, &seed_y);
    return sampler_to_real(sampler_reverse_bits(sampler_owen_reversed(index, seed_x)));
}

/* --- The camera's sampling: anti-aliasing jitter and thin-lens depth of field, in every mode.
 * Always compiled: the sample count is a runtime choice. */

/* Where in the pixel, and where on the lens, sample `sample` of pixel (px, py) goes: sample 0 is
 * the pixel's centre through the lens centre (so one sample renders exactly the un-jittered
 * image); later samples are uniformly random, independent per pixel (the hashed numbers above). */
typedef struct camera_sample {
    real pixel_x, pixel_y; /* offset in the pixel, [0, 1) */
    real lens_x, lens_y;   /* point on the unit disc */
} camera_sample;

inline camera_sample sample_camera(real px, real py, int sample) {
    camera_sample s;
    if (sample == 0) {
        s.pixel_x = s.pixel_y = fgr_real(0.5f);
        s.lens_x = s.lens_y = fgr_real(0.0f);
        return s;
    }
    const uint_lanes h1 = sampler_mix(sampler_pixel_seed(px, py, sample));
    const uint_lanes h2 = sampler_mix(h1), h3 = sampler_mix(h2), h4 = sampler_mix(h3);
    s.pixel_x = sampler_hashed_unit(h1);
    s.pixel_y = sampler_hashed_unit(h2);
    /* Uniform on the disc: radius sqrt(u), angle 2 pi v. */
    real radius = sqrt(sampler_hashed_unit(h3));
    real angle = 6.28318531f * sampler_hashed_unit(h4);
    real cos_angle = fgr_cos(angle), sin_angle = fgr_sin(angle);
    s.lens_x = radius * cos_angle;
    s.lens_y = radius * sin_angle;
    return s;
}
