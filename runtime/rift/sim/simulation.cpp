#include "rift/sim/simulation.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "rift/core/huge_pages.hpp"
#include "rift/core/interrupt.hpp"
#include "rift/core/parallel.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/gmap/state_columns.hpp"
#include "rift/sim/mass_model.hpp"

namespace rift {

Simulation::Simulation(GMap map, const SimulationSettings& settings)
    : map_(std::move(map)), settings_(settings), integrator_(settings.integrator) {
  if (!(settings_.dt > 0)) throw std::invalid_argument("the time step dt must be positive");
  if (!map_.has_embedding(state::kPosition)) {
    throw std::invalid_argument("the map has no 'position' embedding");
  }
  // The state's columns, with the orbits and merge policies of the one table
  // riftc declares them from (rift/core/state_embeddings.hpp).
  position_ = state_embedding<Vec3>(map_, state::kPosition);
  velocity_ = state_embedding<Vec3>(map_, state::kVelocity);
  vertex_mass_ = state_embedding<Real>(map_, state::kVertexMass);
  if (keeps_corner_masses()) corner_mass_ = state_embedding<Real>(map_, state::kCornerMass);
  pinned_ = state_embedding<Bool>(map_, state::kPinned);
}

void Simulation::add_force_model(std::unique_ptr<ForceModel> model) {
  if (initialised_) throw std::logic_error("add_force_model after initialise");
  models_.push_back(std::move(model));
}

void Simulation::add_criterion(std::unique_ptr<Criterion> criterion) {
  if (initialised_) throw std::logic_error("add_criterion after initialise");
  criteria_.push_back(std::move(criterion));
}

void Simulation::set_handles(std::unique_ptr<Handles> handles) {
  if (initialised_) throw std::logic_error("set_handles after initialise");
  handles_ = std::move(handles);
}

void Simulation::add_external_force(std::unique_ptr<ExternalForce> force) {
  if (initialised_) throw std::logic_error("add_external_force after initialise");
  external_.push_back(std::move(force));
}

void Simulation::set_contact(std::unique_ptr<Contact> contact) {
  contact_ = std::move(contact);
}

void Simulation::set_total_mass(Real total_mass) {
  if (!(total_mass > 0)) throw std::invalid_argument("the total mass must be positive");
  if (keeps_corner_masses()) {
    assign_corner_masses_by_total(map_, total_mass, corner_mass_, position_);
  } else {
    element_masses_ = element_masses_by_total(map_, total_mass, position_);
  }
}

void Simulation::set_density(Real density) {
  if (!(density > 0)) throw std::invalid_argument("the density must be positive");
  if (keeps_corner_masses()) {
    assign_corner_masses_by_density(map_, density, corner_mass_, position_);
  } else {
    element_masses_ = element_masses_by_density(map_, density, position_);
  }
}

void Simulation::initialise(SetupPhases* phases) {
  if (keeps_corner_masses()) {
    update_all_vertex_masses(map_, corner_mass_, vertex_mass_);
  } else {
    vertex_masses_from_elements(map_, element_masses_, vertex_mass_);
    element_masses_ = {};
  }
  if (!settings_.rewrites && !criteria_.empty())
    throw std::invalid_argument("a simulation with criteria rewrites its map (settings.rewrites)");
  if (phases) phases->end("vertex masses");
  for (auto& model : models_) {
    model->set_grouping(settings_.group_interactions);
    model->set_lanes(settings_.lanes);
    model->set_rewrites(settings_.rewrites);
    model->set_jacobians_used(is_implicit(settings_.integrator));
    model->initialise(map_);
    if (phases) phases->end("interaction " + model->name());
    if (!keeps_corner_masses()) {
      const ColumnBase* c = map_.find_column(state::kCornerMass);
      if (c && c->allocated()) {
        throw std::logic_error("interaction '" + model->name() +
                               "' reads corner_mass, which this simulation does not keep "
                               "(SimulationSettings::keep_corner_masses)");
      }
    }
  }
  for (auto& criterion : criteria_)
    criterion->initialise(map_);
  if (phases) phases->end("criteria");
  if (Embedding<Vec3> f = map_.embedding<Vec3>(state::kVertexForce)) {
    if (f.orbit() == Orbit::cell(0, map_.dimension())) vertex_force_ = f;
  }
  refresh_inverse_masses();
  if (is_implicit(settings_.integrator)) {
    implicit_ = std::make_unique<ImplicitEuler>(settings_.implicit);
    std::vector<ForceModel*> models;
    models.reserve(models_.size());
    for (auto& model : models_)
      models.push_back(model.get());
    implicit_->set_models(models);
    if (implicit_potential_missing().empty()) {
      // Φ(x) = Σ interaction energies - Σ m g·x over the free vertices (the
      // forces of implicit_step: interactions and gravity).
      implicit_->set_potential([this](const std::vector<Vec3>& x) {
        const ForceInput in{x.data(), velocity_.values().data()};
        Real e = 0;
        for (auto& model : models_)
          e += model->potential_energy(in);
        const std::vector<Real>& mass = vertex_mass_.values();
        for (std::size_t s = 0; s < x.size(); ++s)
          if (is_free_[s]) e -= mass[s] * settings_.gravity.dot(x[s]);
        return e;
      });
    }
  }
  if (phases) phases->end("integrator");
  synced_version_ = map_.topology_version();
  initialised_ = true;
}

std::string Simulation::implicit_potential_missing() const {
  for (const auto& model : models_) {
    if (!model->has_energy()) return "interaction '" + model->name() + "' gives no energy";
  }
  if (!external_.empty()) return "the scene has loads or drag besides gravity";
  return "";
}

void Simulation::refresh_inverse_masses() {
  const std::size_t slots = position_.attachment().slot_capacity();
  inverse_mass_.clear();
  grow_huge(inverse_mass_, slots, Real{0});
  for (Slot s = 0; s < slots; ++s)
    refresh_inverse_mass(s);
  // Held vertices start where their handle puts them.
  if (handles_) {
    handles_->impose(position_.attachment(), time_, settings_.dt, position_.values(),
                     velocity_.values());
  }
}

void Simulation::refresh_touched_inverse_masses() {
  // Only the vertices a rewrite touched (a tear costs what it touches): the
  // vertices on_topology_changed walked, whose slots include the new ones
  // of a split, once each (by the first dart of its run: refreshing at each
  // of a quad cloth's 8 darts of a vertex was 3 % of a tear), and the slots
  // rewrites freed, which must not move (the free list is short: slots are
  // freed only when a whole vertex disappears).
  const OrbitAttachment& att = position_.attachment();
  if (inverse_mass_.size() < att.slot_capacity())
    grow_huge(inverse_mass_, att.slot_capacity(), Real{0});
  for (const auto& [first, end] : vertex_runs_)
    refresh_inverse_mass(att.slot(region_[first]));
  for (Slot s : att.free_slots())
    refresh_inverse_mass(s);
}

void Simulation::refresh_inverse_mass(Slot s) {
  const OrbitAttachment& att = position_.attachment();
  const Real mass = vertex_mass_.values()[s];
  const bool held = handles_ && att.slot_alive(s) && handles_->holds(s, time_);
  inverse_mass_[s] = att.slot_alive(s) && !pinned_.values()[s] && !held && mass > 0 ? 1 / mass : 0;
  // Pinned vertices never move; held ones move as their handle says.
  if (inverse_mass_[s] == 0) {
    velocity_.values()[s] =
        held ? handles_->target_velocity(s, time_, settings_.dt) : Vec3(Vec3::Zero());
  }
}

void Simulation::start_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  const std::size_t n = x.size();
  // The integrator hands the stage buffer back zeroed (forces_zero_): then
  // only slots a tear added need zeros, else the whole array does.
  if (forces_zero_) {
    forces_.resize(n, Vec3::Zero());
  } else {
    forces_.resize(n);
    parallel_for(n, [&](std::size_t s) { forces_[s].setZero(); });
  }
  forces_zero_ = false;
  const ForceInput in{x.data(), v.data()};
  for (auto& model : models_)
    model->clear_accumulated();
  for (auto& model : models_)
    model->add_forces(in, forces_.data(), true);
  if (vertex_force_) {
    // Same orbit as position, so the same slots.
    std::vector<Vec3>& out = vertex_force_.values();
    std::copy(forces_.begin(), forces_.begin() + std::min(n, out.size()), out.begin());
  }
  if (!external_.empty()) {
    // After vertex_force: criteria see internal forces only. Kept apart for
    // the external work.
    const ExternalInput ext{time_, x.data(), v.data(), vertex_mass_.values().data(), n};
    external_forces_.assign(n, Vec3::Zero());
    for (auto& e : external_)
      e->add_forces(map_, ext, external_forces_.data());
    for (std::size_t s = 0; s < n; ++s)
      forces_[s] += external_forces_[s];
  }
}

void Simulation::add_stage_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                  std::vector<Vec3>& f) {
  const ForceInput in{x.data(), v.data()};
  for (auto& model : models_)
    model->add_forces(in, f.data(), false);
  if (!external_.empty()) {
    const ExternalInput ext{time_, x.data(), v.data(), vertex_mass_.values().data(), x.size()};
    for (auto& e : external_)
      e->add_forces(map_, ext, f.data());
  }
}

void Simulation::step() {
  if (!initialised_) initialise();
  throw_if_interrupted();
  // The scales of the divergence check come from the state first stepped
  // (after any deformation or velocity a caller imposed after initialise).
  if (!divergence_.started()) divergence_.start(*this);
  std::vector<Vec3>& x = position_.values();
  std::vector<Vec3>& v = velocity_.values();
  // Forces at the current state are stored in their orbits (criteria read
  // them) and are the integrator's first stage.
  start_forces(x, v);
  tears_last_step_ = criteria_.empty() ? 0 : apply_criteria();
  if (tears_last_step_ > 0) start_forces(x, v);
  // Kept for the step's readers (divergence check, outputs, reactions, the
  // implicit step): a swap, not a copy (24 MB at 10⁶ vertices). forces_ is
  // then free until the next step's start_forces(): the integrator's stage
  // buffer, or the implicit step's start forces with gravity.
  start_forces_.swap(forces_);
  if (handles_) {
    handles_->reactions(position_.attachment(), time_, start_forces_, vertex_mass_.values(),
                        settings_.gravity, reactions_);
  }
  keep_positions_before(x);
  if (implicit_) {
    implicit_step();
  } else {
    // The stages' forces only: the integrator turns them into accelerations
    // in its own sweeps, and hands forces_ back zeroed.
    integrator_.step([this](const std::vector<Vec3>& xs, const std::vector<Vec3>& vs,
                            std::vector<Vec3>& f) { add_stage_forces(xs, vs, f); },
                     ForceToAcceleration{inverse_mass_.data(), settings_.gravity}, x, v,
                     settings_.dt, start_forces_, forces_);
    forces_zero_ = true;
  }
  const Real t0 = time_;
  time_ += settings_.dt;
  ++steps_;
  // Prescribed motions, then contacts, at the end of the step.
  if (handles_ && handles_->releases_between(t0, time_)) refresh_inverse_masses();
  if (handles_) handles_->impose(position_.attachment(), time_, settings_.dt, x, v);
  if (contact_) contact_->project(position_.attachment(), time_, inverse_mass_, x, v);
  account_external_work(x);
  divergence_.check(*this);
}

std::size_t Simulation::apply_criteria() {
  candidates_.clear();
  for (std::uint32_t c = 0; c < criteria_.size(); ++c) {
    const std::size_t first = candidates_.size();
    criteria_[c]->collect(map_, candidates_);
    for (std::size_t k = first; k < candidates_.size(); ++k)
      candidates_[k].criterion = c;
  }
  if (candidates_.empty()) return 0;
  std::sort(candidates_.begin(), candidates_.end(),
            [](const TearCandidate& a, const TearCandidate& b) {
              if (a.criterion != b.criterion) return a.criterion < b.criterion;
              if (a.measure != b.measure) return a.measure > b.measure;
              return a.at < b.at;
            });
  touched_.clear();
  std::size_t applied = 0;
  for (const TearCandidate& c : candidates_) {
    if (settings_.max_tears_per_step > 0 &&
        applied >= static_cast<std::size_t>(settings_.max_tears_per_step)) {
      break;
    }
    throw_if_interrupted();
    if (!map_.is_alive(c.at)) continue;  // removed by an earlier rewrite this step
    if (!criteria_[c.criterion]->apply(map_, c, touched_)) continue;
    ++applied;
    if (settings_.check_each_rewrite) {
      const auto problems = map_.check_validity(5);
      if (!problems.empty()) {
        std::string msg = "step " + std::to_string(steps_ + 1) + ": the G-map is invalid after " +
                          "criterion '" + criteria_[c.criterion]->name() + "' applied at dart " +
                          std::to_string(c.at) + ":";
        for (const auto& p : problems)
          msg += "\n  " + p;
        throw SimulationError(msg);
      }
    }
  }
  // A script may also have written values in place without a rewrite.
  if (applied > 0 || !touched_.empty()) {
    on_topology_changed(touched_);
    tears_ += applied;
  }
  return applied;
}

void Simulation::keep_positions_before(const std::vector<Vec3>& x) {
  if (!external_.empty()) {
    x_before_ = x;  // loads act on every vertex
  } else if (handles_) {
    // Only handles do work: their vertices' positions are enough.
    const std::vector<Slot>& held = handles_->held_slots(position_.attachment());
    held_x_before_.resize(held.size());
    for (std::size_t k = 0; k < held.size(); ++k)
      held_x_before_[k] = held[k] < x.size() ? x[held[k]] : Vec3(Vec3::Zero());
  }
}

void Simulation::account_external_work(const std::vector<Vec3>& x) {
  // W += sum over vertices of (external force + handle reaction) . dx, with
  // the forces at the start of the step (first order in dt).
  if (!tracks_external_work()) return;
  const auto& mass = vertex_mass_.values();
  const Real t0 = time_ - settings_.dt;
  // Adds the reaction of a handle on a vertex it held during the step.
  auto add_reaction = [&](Slot s, Vec3& f) {
    if (handles_ && inverse_mass_[s] == 0 && handles_->holds(s, t0)) {
      f += -(start_forces_[s] + mass[s] * settings_.gravity);
    }
  };
  if (external_.empty()) {
    // Handles only: the other vertices' terms are 0 · dx, which leave the
    // sum's bits as they are, so the held slots alone (ascending, the order
    // of a sweep of every slot) give the same sum.
    const std::vector<Slot>& held = handles_->held_slots(position_.attachment());
    for (std::size_t k = 0; k < held.size() && k < held_x_before_.size(); ++k) {
      const Slot s = held[k];
      if (s >= x.size()) continue;
      Vec3 f = Vec3::Zero();
      add_reaction(s, f);
      external_work_ += f.dot(x[s] - held_x_before_[k]);
    }
    return;
  }
  const bool any_external = !external_forces_.empty();
  const OrbitAttachment& att = position_.attachment();
  const std::size_t n = std::min(x.size(), x_before_.size());
  for (Slot s = 0; s < n; ++s) {
    if (!att.slot_alive(s)) continue;
    Vec3 f = any_external && s < external_forces_.size() ? external_forces_[s] : Vec3::Zero();
    add_reaction(s, f);
    external_work_ += f.dot(x[s] - x_before_[s]);
  }
}

void Simulation::on_topology_changed(std::span<const Dart> touched) {
  if (!settings_.rewrites) {
    throw std::logic_error(
        "on_topology_changed: the simulation was set up for a map that is never rewritten "
        "(SimulationSettings::rewrites)");
  }
  const Orbit vertex = Orbit::cell(0, map_.dimension());
  const Mark m = map_.reserve_mark();
  region_.clear();
  vertex_runs_.clear();
  for (Dart d : touched) {
    if (!map_.is_alive(d)) {
      region_.push_back(d);  // deleted: its matches must be dropped
      continue;
    }
    if (map_.is_marked(d, m)) continue;
    const auto first = static_cast<std::uint32_t>(region_.size());
    map_.for_each_in_orbit(d, vertex, [&](Dart x) {
      map_.mark(x, m);
      region_.push_back(x);
    });
    vertex_runs_.emplace_back(first, static_cast<std::uint32_t>(region_.size()));
  }
  // Each touched vertex's mass from the darts just walked, in the walk's
  // order: the bits of a walk of its corners, without walking it again (a
  // tenth of a tear of the 10^6-vertex cloth went to that walk and its
  // marks). On a large map each corner's slot and mass is a miss: they are
  // asked for all at once first, so that the misses overlap.
  const OrbitAttachment& corners = corner_mass_.attachment();
  if (map_.capacity() >= kPrefetchFromDarts && !corners.dormant()) {
    if (const Slot* slot = corners.slot_data()) {  // null by dart: nothing to read
      for (const auto& [first, end] : vertex_runs_) {
        for (std::uint32_t k = first; k < end; ++k)
          prefetch(slot + region_[k]);
      }
    }
    const EmbeddingReader<Real> mass = std::as_const(corner_mass_).reader();
    for (const auto& [first, end] : vertex_runs_) {
      for (std::uint32_t k = first; k < end; ++k) {
        if (mass.slot(region_[k]) < corners.slot_capacity()) prefetch(&mass[region_[k]]);
      }
    }
  }
  for (const auto& [first, end] : vertex_runs_) {
    update_vertex_mass(map_, std::span<const Dart>(region_).subspan(first, end - first),
                       corner_mass_, vertex_mass_);
  }
  for (Dart d : region_)
    map_.unmark(d, m);
  map_.free_mark(m);
  // The touched darts alone: every dart whose links or slots changed is
  // among them, which is all a re-match needs (reach.hpp); their whole
  // vertex orbits, three to eight times as many darts, only made each
  // interaction look at more orbits.
  for (auto& model : models_)
    model->rematch(map_, touched);
  for (auto& criterion : criteria_)
    criterion->topology_changed(map_, touched, synced_version_);
  synced_version_ = map_.topology_version();
  if (handles_) handles_->topology_changed(map_, region_);
  if (implicit_) implicit_->topology_changed();
  bdf2_.restart();  // the slots' history no longer matches the map
  refresh_touched_inverse_masses();
}

std::size_t Simulation::per_vertex_bytes() const {
  std::size_t bytes = integrator_.buffer_bytes() + inverse_mass_.capacity() * sizeof(Real) +
                      is_free_.capacity() * sizeof(char);
  for (const std::vector<Vec3>* a :
       {&forces_, &start_forces_, &external_forces_, &x_before_, &held_x_before_, &target_v_})
    bytes += a->capacity() * sizeof(Vec3);
  return bytes;
}

void Simulation::report_memory(MemoryReport& report) const {
  map_.report_memory(report);
  report.add("integrator", "stage arrays", integrator_.buffer_bytes());
  if (implicit_) implicit_->report_memory(report);
  bdf2_.report_memory(report);
  report.add("simulation", "forces", forces_);
  report.add("simulation", "start forces", start_forces_);
  report.add("simulation", "inverse masses", inverse_mass_);
  report.add("simulation", "free flags (implicit)", is_free_);
  report.add("simulation", "target velocities (implicit)", target_v_);
  report.add("simulation", "external forces", external_forces_);
  report.add("simulation", "positions before the step", x_before_);
  report.add("simulation", "handle reactions", reactions_);
  report.add("simulation", "held positions before the step", held_x_before_);
  for (const auto& model : models_)
    model->report_memory(report);
  for (const auto& criterion : criteria_)
    criterion->report_memory(report);
}

Real Simulation::kinetic_energy() const {
  Real e = 0;
  map_.for_each_cell(Orbit::cell(0, map_.dimension()),
                     [&](Dart d) { e += 0.5 * vertex_mass_[d] * velocity_[d].squaredNorm(); });
  return e;
}

Real Simulation::potential_energy() const {
  Real e = 0;
  map_.for_each_cell(Orbit::cell(0, map_.dimension()),
                     [&](Dart d) { e -= vertex_mass_[d] * settings_.gravity.dot(position_[d]); });
  const ForceInput in{position_.values().data(), velocity_.values().data()};
  for (const auto& model : models_)
    e += model->potential_energy(in);
  return e;
}

Vec3 Simulation::momentum() const {
  Vec3 p = Vec3::Zero();
  map_.for_each_cell(Orbit::cell(0, map_.dimension()),
                     [&](Dart d) { p += vertex_mass_[d] * velocity_[d]; });
  return p;
}

Real Simulation::total_mass() const {
  Real m = 0;
  map_.for_each_cell(Orbit::cell(0, map_.dimension()), [&](Dart d) { m += vertex_mass_[d]; });
  return m;
}

}  // namespace rift
