#pragma once
// Spin at a contact (docs/physics.md, "Spin and rolling"). Particles are solid spheres: a contact
// between particle i and particle j (or a collider) with unit normal n towards i touches i at
// -r_i n from its centre and j at +r_j n from its. The surfaces there move apart along the contact
// at v_i - v_j - (r_i ω_i + r_j ω_j) × n, and an impulse J along the surface (on i, -J on j) turns
// i by -a_i r_i n × J and j by -a_j r_j n × J (a the inverse moment of inertia): the sliding it
// stops costs J (w_i + w_j + a_i r_i² + a_j r_j²), so that a contact's friction turns sliding into
// rolling by itself. Along the normal nothing changes: a sphere's normal passes through its centre.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace core {

// one contact's levers and inverse inertias: r_j = 0 and a_j = 0 for a collider, a = 0 for a side
// that does not turn (pinned, or without spin in the plan)
struct ContactLevers {
    double ri = 0.0, rj = 0.0;  // m
    double ai = 0.0, aj = 0.0;  // 1/(kg m²)
    // what the spin adds to the inverse mass of sliding along the surface
    double turning() const { return ai * ri * ri + aj * rj * rj; }
};

// the surface velocity the spins add to the contact's relative velocity (always along the surface)
inline Eigen::Vector3d spinSlip(const ContactLevers &l, const Eigen::Vector3d &omegaI, const Eigen::Vector3d &omegaJ,
                                const Eigen::Vector3d &normal)
{
    return -(l.ri * omegaI + l.rj * omegaJ).cross(normal);
}

// the turn a surface impulse J on i (and -J on j) gives each side
inline void turnBy(const ContactLevers &l, const Eigen::Vector3d &normal, const Eigen::Vector3d &impulse,
                   Eigen::Ref<Eigen::Vector3d> omegaI, Eigen::Ref<Eigen::Vector3d> omegaJ)
{
    const Eigen::Vector3d arm = normal.cross(impulse);
    omegaI -= (l.ai * l.ri) * arm;
    omegaJ -= (l.aj * l.rj) * arm;
}

// the radius rolling resistance and spinning friction act at: a particle's own on a collider, the
// reduced radius r_i r_j / (r_i + r_j) between two
inline double rollingRadius(const ContactLevers &l)
{
    if (l.rj == 0.0)
        return l.ri;
    return l.ri + l.rj > 0.0 ? l.ri * l.rj / (l.ri + l.rj) : 0.0;
}

// the orientation q (w, x, y, z) turned by a constant spin ω for a time h: q' = exp(½ h ω) q, exact
// for a spin that does not change, renormalised against rounding
inline Eigen::Vector4d turned(const Eigen::Vector4d &q, const Eigen::Vector3d &omega, double h)
{
    const double angle = omega.norm() * h;
    if (!(angle > 0.0))
        return q;
    const Eigen::Vector3d axis = omega.normalized();
    const Eigen::Quaterniond step(Eigen::AngleAxisd(angle, axis));
    const Eigen::Quaterniond now(q[0], q[1], q[2], q[3]);
    Eigen::Quaterniond next = step * now;
    next.normalize();
    return {next.w(), next.x(), next.y(), next.z()};
}

}  // namespace core
