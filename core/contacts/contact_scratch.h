#pragma once
// What the iterative contact solver (contacts.cpp) keeps between its passes within a sub-step:
// where each particle started, the impacts found along the paths, the contacts it solves and their
// accumulated impulses. All of it is rebuilt every sub-step and lives in the Workspace, so that a
// step allocates nothing once the arrays have reached the scene's size; the one thing that carries
// over, the impulses the next sub-step starts from, is in the State (State::contactImpulses), so
// that a resumed run solves exactly as the run it continues.

#include "core/contacts/contact_spin.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace core {

// the inverse masses of a contact's two sides, 1/kg (0 for a side that stands still), and with
// spin their inverse moments of inertia
struct Weights {
    double i = 0.0, j = 0.0;
    double mass = 0.0;  // kg, 1 / (i + j): the contact's effective mass (0 when neither side moves)
    // with spin (contact_spin.h): the levers and inverse inertias, the effective mass of sliding
    // along the surface, and of turning one side against the other (0 when neither turns)
    ContactLevers levers;
    double tangentMass = 0.0;  // kg
    double angularMass = 0.0;  // kg m²
    double sum() const { return i + j; }
};

// a contact of free particle i with particle j, or with collider -1 - j when j < 0
struct Contact {
    int i = 0;
    int j = 0;
    int order = 0;  // the level it is solved at: lowest first (contacts.cpp, "shock propagation")
    double side = 1.0;                                 // a collider's side particle i started on
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // unit, towards i
    double targetSpeed = 0.0;       // m/s, the separating normal speed the solve aims at
    double drift = 0.0;             // s: how far its impulses move the sub-step's end, per m/s they add
    double friction = 0.0;          // μk
    double staticFriction = 0.0;    // μs
    double rollingFriction = 0.0;   // μr
    double spinningFriction = 0.0;  // about the normal
    double normalImpulse = 0.0;     // per unit inverse mass: N·s, accumulated over the iterations
    Eigen::Vector3d frictionImpulse = Eigen::Vector3d::Zero();  // N·s, accumulated
    // with spin: the angular impulses of rolling resistance (along the surface) and spinning
    // friction (about the normal), N·m·s, accumulated
    Eigen::Vector3d rollingImpulse = Eigen::Vector3d::Zero();
    double spinningImpulse = 0.0;
    double pushed = 0.0;            // m·kg, the position correction along the normal, accumulated
    Eigen::Vector3d heldBack = Eigen::Vector3d::Zero();  // m·kg, friction's correction along the surface
    Weights weights;       // in the solves' iterations
    Weights shockWeights;  // in their last: the side nearer the ground stands still
    bool deferred = false;  // a near miss closing faster than a resting contact
    bool bounce = false;    // overlapping and closing faster than a resting contact: an impact
    bool stuck = false;  // the position solve held it in place along its surface

    bool withCollider() const { return j < 0; }
    int collider() const { return -1 - j; }
};

// an impact found along the paths: the time within the sub-step, and the pair or particle and collider
struct Impact {
    double time = 0.0;  // s since the sub-step began
    int i = 0;
    int j = 0;  // as Contact::j
    // the particles' path versions it was found on (ContactScratch::version): an impact found on a
    // path that a later impact has changed is stale
    std::uint32_t versionI = 0;
    std::uint32_t versionJ = 0;

    bool operator<(const Impact &other) const
    {
        if (time != other.time)
            return time < other.time;
        if (i != other.i)
            return i < other.i;
        return j < other.j;
    }
};

// where a particle's path through the rest of the sub-step begins, once an impact has changed it
struct PathSegment {
    double time = 0.0;                                  // s since the sub-step began
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, at that time
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s, just after the impact
};

struct ContactScratch {
    Eigen::Matrix3Xd startPosition;  // m, at the sub-step's start
    Eigen::Matrix3Xd startVelocity;  // m/s
    // m, where each particle ended the impacts (where a collider is two-sided; else empty): the
    // side of a table it keeps in the resting solve. Not the side it began the sub-step on, as a
    // ball may pass round the table's edge; the impacts let nothing through the top
    Eigen::Matrix3Xd sidePosition;
    Eigen::Vector3d sidePointOf(int i) const
    {
        return sidePosition.cols() > i ? sidePosition.col(i) : startPosition.col(i);
    }
    Eigen::Matrix3Xd sweptCentre;    // m, the middle of each particle's move through the sub-step
    Eigen::VectorXd sweptRadius;     // m, a sphere about it holding the particle all along its path
    std::vector<int> fast;               // the particles that move too far for the grid this sub-step
    std::vector<std::uint8_t> isFast;    // per particle

    // the impacts to resolve, a heap ordered by time (earliest on top)
    std::vector<Impact> impacts;
    // per particle: the segment its path now starts with (-1: the integrator's whole path), and how
    // often an impact has changed its path in this sub-step
    std::vector<int> segmentOf;
    std::vector<PathSegment> segments;
    std::vector<std::uint32_t> version;
    // the candidate pairs of the last broad phase as adjacency lists: p's are
    // candidates[candidateStart[p] .. candidateStart[p + 1])
    std::vector<int> candidateStart;
    std::vector<int> candidates;
    // particles whose path an impact took out of the sphere the broad phase held it in: their
    // candidates are found again once the impacts in hand are resolved
    std::vector<int> strays;
    std::vector<std::uint8_t> isStray;

    double drift = 0.0;  // s: β h, how far the velocity solve's changes move the sub-step's end, per m/s
    double subStep = 0.0;  // s, h
    bool spin = false;     // the plan's spin: contacts act at the particles' surfaces and turn them

    std::vector<Contact> contacts;  // as found, then in the order they are solved (sorted by level)
    // where the particles were when the contacts were gathered, and what the solve found after:
    // which particles it moved farther than their gathering allowed for, and the pairs already
    // contacts (as i · n + j, i < j, sorted), so that a pair it pushed together is found
    // (contact_solve.cpp, gatherNewOverlaps)
    Eigen::Matrix3Xd gatherPosition;
    std::vector<std::uint8_t> movedFar;
    std::vector<int> movers;
    std::vector<std::uint64_t> pairKeys;
    std::uint64_t overlapsCaught = 0;  // pairs the solve pushed together, found and solved, for the tests
    std::vector<int> place;         // while sorting: where each contact goes
    // the pair contacts as an adjacency list, for the levels: particle p's neighbours are
    // neighbours[neighbourStart[p] .. neighbourStart[p + 1])
    std::vector<int> neighbourStart;
    std::vector<int> neighbours;
    std::vector<int> level;  // per particle: contacts between it and the ground, by breadth-first search
    std::vector<int> queue;
    std::vector<int> levelStart;  // counting sort of the contacts by level
    // the fail-safe's impact zones (contact_solve.cpp, stopClosingContacts): per particle, its zone
    // (union-find), and per zone its momentum and mass
    std::vector<int> zoneOf;
    Eigen::Matrix3Xd zoneMomentum;
    std::vector<double> zoneMass;

    std::uint64_t impactsResolved = 0;  // impacts resolved so far, for the tests
    // impacts left to the resting contacts because a sub-step met more than kMaxImpactEvents (a
    // jammed elastic crowd): counted so that a run can say so
    std::uint64_t impactsLeft = 0;
    // what each thread's share of a parallel search found, joined in share order afterwards so
    // that the result is the same on any thread count: impacts, fast particles, contacts
    std::vector<std::vector<Impact>> impactShares;
    std::vector<std::vector<int>> fastShares;
    std::vector<std::vector<Contact>> contactShares;
    std::uint64_t zonesMade = 0;  // jams made impact zones so far (contact_impacts.cpp), for the tests
    std::vector<int> zoneMembers;       // a jam's impact zone
    std::vector<int> zoneQueue;         // its members, searched for their next impacts
    std::vector<std::uint8_t> inZone;   // per particle: in the zone (or a pinned particle it met)
    std::vector<int> zonePinnedMet;     // the pinned particles a jam's zone met, marked in inZone
};

}  // namespace core
