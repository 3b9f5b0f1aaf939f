#pragma once
// The broad phase of particle contacts: which pairs overlap at the start of the pass. Both
// functions give the same list, every pair i < j with ‖x_i − x_j‖ < r_i + r_j and at least one of
// the two free, in lexicographic (i, j) order; a particle whose position is not finite is in none.

#include "core/contacts/contact_grid.h"
#include "core/model/model.h"

#include <Eigen/Core>
#include <vector>

namespace core {

// a uniform grid hashed into buckets, O(n) for particles of similar sizes; fills grid.pairs
void findContacts(const Model &model, const Eigen::Matrix3Xd &position, ContactGrid &grid);
// the same with other radii than the model's (the contact solver's swept spheres: each particle's
// path through the sub-step inside a sphere about its midpoint)
void findContacts(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid);

// every pair tested, O(n²): the reference the grid must match exactly
void findContactsBruteForce(const Model &model, const Eigen::Matrix3Xd &position, std::vector<ContactPair> &pairs);
void findContactsBruteForce(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius,
                            std::vector<ContactPair> &pairs);

}  // namespace core
