#version 450
// RANSAC fit of T(s) = ρs + φ per path (Bénard et al. 2010, §4.2): one workgroup per path,
// one hypothesis per invocation per round. Mirrors engine/coherence/ransac.cpp: the same
// hash-drawn vote pairs, the same rounds of 64 hypotheses, the same choice of the best one
// (most inliers, lowest index on ties), then least squares on its inliers.
layout(local_size_x = 64) in;

struct Vote { float t; float s; };
struct Fit { float rho; float phi; uint votes; uint inliers; uint iterations; uint fitted; uint pad0; uint pad1; };

layout(std430, binding = 0) readonly buffer Votes { Vote votes[]; };
layout(std430, binding = 1) readonly buffer Offsets { uint offsets[]; };  // path p: [offsets[p], offsets[p+1])
layout(std430, binding = 2) writeonly buffer Fits { Fit fits[]; };

layout(push_constant) uniform RansacPush {
    float outlier_ratio;
    float target_probability;
    float inlier_px;
    uint max_iterations;
    uint seed;
    uint path_count;
} pc;

shared uint s_count[64];
shared uint s_h[64];
shared float s_rho[64];
shared float s_phi[64];
shared float s_a[64];
shared float s_b[64];
shared uint s_m[64];

uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint iterations_for(float inlier_ratio) {
    float w2 = inlier_ratio * inlier_ratio;
    if (w2 >= 1.0) return 1u;
    if (w2 <= 0.0) return pc.max_iterations;
    float n = ceil(log(1.0 - pc.target_probability) / log(1.0 - w2));
    return uint(clamp(n, 1.0, float(pc.max_iterations)));
}

void main() {
    uint path = gl_WorkGroupID.x;
    if (path >= pc.path_count) return;
    uint tid = gl_LocalInvocationID.x;
    uint first = offsets[path];
    uint n = offsets[path + 1u] - first;
    if (n < 2u) {
        if (tid == 0u) fits[path] = Fit(0.0, 0.0, n, 0u, 0u, 0u, 0u, 0u);
        return;
    }

    uint needed = iterations_for(1.0 - pc.outlier_ratio);
    uint best_count = 0u, best_h = 0u;
    float best_rho = 0.0, best_phi = 0.0;
    uint done = 0u;
    while (done < needed) {  // uniform: every invocation holds the same `needed` and `done`
        uint h = done + tid;
        uint base = pcg_hash(pc.seed ^ pcg_hash(path * 2654435761u ^ pcg_hash(h)));
        uint a = base % n;
        uint b = pcg_hash(base) % (n - 1u);
        if (b >= a) b++;
        Vote va = votes[first + a], vb = votes[first + b];
        uint count = 0u;
        precise float ds = vb.s - va.s;
        precise float rho = ds != 0.0 ? (vb.t - va.t) / ds : 0.0;
        precise float phi = va.t - rho * va.s;
        bool usable = ds != 0.0 && !isnan(rho) && !isinf(rho) && rho != 0.0;
        if (usable) {
            precise float limit = pc.inlier_px * abs(rho);
            for (uint k = 0u; k < n; ++k) {
                Vote v = votes[first + k];
                precise float r = abs(v.t - (rho * v.s + phi));
                if (r <= limit) count++;
            }
        }
        s_count[tid] = count;
        s_h[tid] = h;
        s_rho[tid] = rho;
        s_phi[tid] = phi;
        barrier();
        // The best of this round: most inliers, then lowest hypothesis index.
        for (uint stride = 32u; stride > 0u; stride >>= 1u) {
            if (tid < stride) {
                uint o = tid + stride;
                if (s_count[o] > s_count[tid] || (s_count[o] == s_count[tid] && s_h[o] < s_h[tid])) {
                    s_count[tid] = s_count[o];
                    s_h[tid] = s_h[o];
                    s_rho[tid] = s_rho[o];
                    s_phi[tid] = s_phi[o];
                }
            }
            barrier();
        }
        if (s_count[0] > best_count) {
            best_count = s_count[0];
            best_h = s_h[0];
            best_rho = s_rho[0];
            best_phi = s_phi[0];
        }
        barrier();
        done += 64u;
        if (best_count > 0u) needed = min(needed, iterations_for(float(best_count) / float(n)));
    }

    if (best_count < 2u) {
        if (tid == 0u) fits[path] = Fit(0.0, 0.0, n, 0u, done, 0u, 0u, 0u);
        return;
    }
    // Least squares on the inliers, s centred: two reductions (means, then moments).
    precise float limit = pc.inlier_px * abs(best_rho);
    float sum_s = 0.0, sum_t = 0.0;
    uint m = 0u;
    for (uint k = tid; k < n; k += 64u) {
        Vote v = votes[first + k];
        precise float r = abs(v.t - (best_rho * v.s + best_phi));
        if (r <= limit) { sum_s += v.s; sum_t += v.t; m++; }
    }
    s_a[tid] = sum_s; s_b[tid] = sum_t; s_m[tid] = m;
    barrier();
    for (uint stride = 32u; stride > 0u; stride >>= 1u) {
        if (tid < stride) { s_a[tid] += s_a[tid + stride]; s_b[tid] += s_b[tid + stride]; s_m[tid] += s_m[tid + stride]; }
        barrier();
    }
    float total = float(s_m[0]);
    float mean_s = s_a[0] / total, mean_t = s_b[0] / total;
    uint inliers = s_m[0];
    barrier();
    float sss = 0.0, sst = 0.0;
    for (uint k = tid; k < n; k += 64u) {
        Vote v = votes[first + k];
        precise float r = abs(v.t - (best_rho * v.s + best_phi));
        if (r <= limit) { sss += (v.s - mean_s) * (v.s - mean_s); sst += (v.s - mean_s) * (v.t - mean_t); }
    }
    s_a[tid] = sss; s_b[tid] = sst;
    barrier();
    for (uint stride = 32u; stride > 0u; stride >>= 1u) {
        if (tid < stride) { s_a[tid] += s_a[tid + stride]; s_b[tid] += s_b[tid + stride]; }
        barrier();
    }
    if (tid == 0u) {
        float rho = s_a[0] > 0.0 ? s_b[0] / s_a[0] : 0.0;
        float phi = mean_t - rho * mean_s;
        bool ok = s_a[0] > 0.0 && !isnan(rho) && !isinf(rho) && rho != 0.0 && !isnan(phi) && !isinf(phi);
        fits[path] = Fit(rho, phi, n, inliers, done, ok ? 1u : 0u, 0u, 0u);
    }
}
