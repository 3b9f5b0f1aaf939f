#pragma once
// Carrying a run across an edit of its scene.
//
// An edit in the editor does not start the run again unless it has to: what the edit left alone
// goes on moving, and what it made new starts from its description. How much survives depends on
// the kind of edit (SceneChange, messages.h):
//
// - Parameters: the same particles and springs, other values. The state stays as it is, broken
//   springs included.
// - Structure: particles or springs added, removed or changed. Each particle the edit left as it
//   was keeps its motion, and every other starts from its description. Broken springs stay broken
//   only while the spring list is the same, since a flag belongs to a spring by its index.
// - InitialConditions: Use Current State as Initial (core::storeState) or its undo. The particles
//   are the same and the run goes on with the same bits; the spring lists before and after differ
//   by the springs that broke alone, so each flag and each entry of the break log follows its
//   spring to its index in the new list.
// - Replace: another scene. Nothing is carried.
//
// Matching needs no ids, because edits keep the order of particles and springs. Walking both
// lists in step pairs each survivor with itself: by index when the count is the same, else with
// the next one of the same description, so that a deletion skips old entries and an addition
// matches none. Neighbours of the same description cannot be told apart: the first one found is
// taken.
//
// The runner calls carryAcrossEdit() for each scene it is given; the pieces are free functions of
// plain values, so that the tests can drive them without a runner.

#include "messages.h"

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"

namespace ui {

// whether two scenes hold the same particles, springs and planes, so that a state of one is a
// state of the other (they may differ in settings and per-spring values)
bool sameStructure(const core::SceneDesc &a, const core::SceneDesc &b);

// Carries state, a state of a run of previous (null: there was none), across the edit `change` that
// made scene, compiled as model. False when nothing can be carried (another scene, no previous
// one, or a state that is not of previous): the run must then start from scene's initial state.
bool carryAcrossEdit(const core::SceneDesc *previous, const core::SceneDesc &scene, const core::Model &model,
                     SceneChange change, core::State &state);

// A Structure edit: a state of scene in which each particle that previous had with the same
// description keeps its motion in state (unless it is pinned now), and every other starts from
// its description; time and step go on, and so do broken springs if the spring list is the same.
core::State carryMotion(const core::SceneDesc &previous, const core::SceneDesc &scene, const core::Model &model,
                        const core::State &state);

// An InitialConditions edit: the spring lists of previous and scene differ by broken springs
// alone. A spring in both keeps its flag and its entries in the break log; one that scene left out
// leaves the log; one that scene has again and previous had not broke in this run.
void carryBrokenSprings(const core::SceneDesc &previous, const core::SceneDesc &scene, const core::Model &model,
                        core::State &state);

}  // namespace ui
