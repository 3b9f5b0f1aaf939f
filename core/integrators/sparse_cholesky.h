#pragma once
// The sparse Cholesky factorisations of the stiff solvers (projective.cpp, implicit_euler.cpp):
// CHOLMOD's simplicial ones where the build found it (SPRINGLAB_CHOLMOD), else Eigen's. Both take
// the same calls (compute, analyzePattern, factorize, info, solve). CHOLMOD picks the better of its
// orderings (minimum degree or nested dissection): on a 128 × 128 cloth's matrix its back-
// substitution for three coordinates took 3.05 ms against Eigen's 8.02 ms, to the same answer
// within 2e-15. A factor's solve is not safe to call from two threads at once (CHOLMOD's workspace
// is shared): solve all coordinates in one call.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#ifdef SPRINGLAB_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace core {

#ifdef SPRINGLAB_CHOLMOD
using SparseLlt = Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>>;
using SparseLdlt = Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>>;
#else
using SparseLlt = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>;
using SparseLdlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
#endif

}  // namespace core
