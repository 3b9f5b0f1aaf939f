#pragma once
// A particle's path through one sub-step, as the contact solver sees it: the motion the integrator
// made between the position and velocity at the sub-step's start and end, so that an impact found
// on it happens when it would have happened in the integrator's own motion, not at the sub-step's
// end. The Euler schemes move in a straight line (symplectic and implicit Euler with the new
// velocity after their kick, explicit Euler with the old one before its kick); the higher-order
// schemes along the cubic Hermite curve through both ends, exact for motion under a constant force
// and otherwise as close as their own step.

#include "core/integrators/integrator.h"

#include <Eigen/Core>
#include <algorithm>

namespace core {

enum class PathShape {
    KickDrift,  // symplectic and implicit Euler, xpbd: v changes at the start, x moves with the new v
    DriftKick,  // explicit Euler: x moves with the old v, v changes at the end
    Hermite,    // velocity Verlet, RK4, adaptive RK45
};

inline PathShape pathShape(Integrator integrator)
{
    switch (integrator) {
    case Integrator::SymplecticEuler:
    case Integrator::ImplicitEuler:
    case Integrator::Xpbd:  // its velocity is the move it made: (x1 - x0) / h
    case Integrator::Projective:
    case Integrator::Vbd:
        return PathShape::KickDrift;
    case Integrator::ExplicitEuler:
        return PathShape::DriftKick;
    case Integrator::VelocityVerlet:
    case Integrator::Rk4:
    case Integrator::AdaptiveRk45:
        break;
    }
    return PathShape::Hermite;
}

// β: how far a change of the sub-step's end velocity moves its end position, per unit of the change
// and of h, under a constant force (x1 − x0 − v0 h = β (v1 − v0) h): 1 for the kick-drift Euler
// schemes, ½ for the second-order ones, 0 for explicit Euler, whose position moves with the old
// velocity
inline double driftWeight(PathShape shape)
{
    switch (shape) {
    case PathShape::KickDrift:
        return 1.0;
    case PathShape::DriftKick:
        return 0.0;
    case PathShape::Hermite:
        break;
    }
    return 0.5;
}

struct ParticlePath {
    PathShape shape = PathShape::Hermite;
    Eigen::Vector3d x0, v0, x1, v1;  // m, m/s at the sub-step's start (t = 0) and end (t = h)
    double h = 0.0;                  // s

    // the velocity the straight paths move with
    const Eigen::Vector3d &drift() const { return shape == PathShape::KickDrift ? v1 : v0; }

    Eigen::Vector3d position(double t) const
    {
        if (shape != PathShape::Hermite)
            return x0 + t * drift();
        // (as x0 plus the way from it: the weights of x0 and x1 sum to one only up to rounding, so
        // a row at rest across, all at one height, would drift apart across by an ulp an impact
        // and, elastic impacts multiplying it, leave its line within a few steps)
        const double s = t / h;
        const double s2 = s * s, s3 = s2 * s;
        return x0 + ((s3 - 2 * s2 + s) * h) * v0 + (3 * s2 - 2 * s3) * (x1 - x0) + ((s3 - s2) * h) * v1;
    }
    Eigen::Vector3d velocity(double t) const
    {
        if (shape != PathShape::Hermite)
            return drift();
        const double s = t / h;
        const double s2 = s * s;
        return ((6 * s - 6 * s2) / h) * (x1 - x0) + (3 * s2 - 4 * s + 1) * v0 + (3 * s2 - 2 * s) * v1;
    }
    Eigen::Vector3d acceleration(double t) const
    {
        const double s = t / h;
        return ((6 - 12 * s) / (h * h)) * (x1 - x0) + ((6 * s - 4) / h) * v0 + ((6 * s - 2) / h) * v1;
    }
    // a bound on the speed along the whole path: a Hermite curve's velocity is a quadratic Bézier
    // curve, inside the hull of its three control points
    double speedBound() const
    {
        if (shape != PathShape::Hermite)
            return drift().norm();
        const Eigen::Vector3d middle = (3.0 / h) * (x1 - x0) - v0 - v1;
        return std::max({v0.norm(), middle.norm(), v1.norm()});
    }
    // where the particle ends the sub-step when its velocity becomes v at time t: on along the
    // same kind of motion for the rest of the sub-step
    void goOn(double t, const Eigen::Vector3d &v, Eigen::Vector3d &x, Eigen::Vector3d &vEnd) const
    {
        const double tau = h - t;
        switch (shape) {
        case PathShape::KickDrift:
            x = position(t) + tau * v;
            vEnd = v;
            return;
        case PathShape::DriftKick:
            x = position(t) + tau * v;
            vEnd = v + (v1 - v0);  // the kick at the end still comes
            return;
        case PathShape::Hermite:
            break;
        }
        const Eigen::Vector3d a = acceleration(t);
        x = position(t) + tau * v + (0.5 * tau * tau) * a;
        vEnd = v + tau * a;
    }
};

}  // namespace core
