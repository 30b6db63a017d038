#include "rig/campaign/plant_motion.hpp"

#include <algorithm>
#include <iterator>
#include <numbers>
#include <utility>

namespace hilrig::campaign {

std::unique_ptr<plants::Plant> make_plant(const PlantSpec& spec) {
  switch (spec.kind) {
  case PlantKind::Press:
    return std::make_unique<plants::PressPlant>(spec.press, spec.press_start, spec.step, spec.press_changes);
  case PlantKind::RotaryAxis:
    return std::make_unique<plants::RotaryAxis>(spec.rotary, spec.rotary_start, spec.step,
                                                spec.rotary_changes);
  case PlantKind::StepperLoad:
    return std::make_unique<plants::StepperLoad>(spec.stepper, spec.step, spec.stepper_changes);
  }
  return nullptr;
}

PlantMotion::PlantMotion(const PlantSpec& spec, double counts_per_turn, Nanos end, Resume resume)
    : per_rad_(counts_per_turn / (2.0 * std::numbers::pi)), end_(end), ahead_(spec.step * kPlanSteps) {
  checkpoint_ = make_plant(spec);
  knots_.push_back(checkpoint_->state());
  keep_knots_ = resume == Resume::AtKnot && checkpoint_->resumes_at_knots();
  horizon_ = knots_.front().time;
  if (spec.step > Nanos::zero() && end > horizon_) {
    const auto steps = static_cast<std::size_t>((end - horizon_).count() / spec.step.count());
    history_.reserve(std::min(steps + steps / 5 + 64, kHistoryReservedMax));
  }
  input(knots_.front().time, plants::PlantInput::Valve,
        spec.kind != PlantKind::Press || spec.press_start.valve);
}

signals::Segment PlantMotion::segment(const plants::Knot& a, const plants::Knot& b) const {
  const double d = (b.time - a.time).seconds();
  const double p0 = a.angle * per_rad_;
  const double v0 = a.speed * per_rad_;
  // Through both knots' positions; into a standstill, to speed 0 exactly (a constant
  // torque makes the two the same).
  const double acc =
      b.speed == 0.0 && a.speed != 0.0 ? -v0 / d : 2.0 * (b.angle * per_rad_ - p0 - v0 * d) / (d * d);
  return signals::Segment{a.time, b.time - a.time, p0, v0, acc};
}

void PlantMotion::integrate(plants::Plant& plant, Nanos until, std::vector<signals::Segment>& out) const {
  plants::Knot prev = plant.state();
  while (prev.time < until) {
    const plants::Knot k = plant.advance(until);
    if (k.time > prev.time) out.push_back(segment(prev, k));
    prev = k;
  }
}

std::size_t PlantMotion::resume_knot(Nanos t) const {
  if (!keep_knots_) return 0;
  const auto after = std::upper_bound(knots_.begin(), knots_.end(), t,
                                      [](Nanos v, const plants::Knot& k) { return v < k.time; });
  if (after == knots_.begin()) return 0;
  auto i = static_cast<std::size_t>(after - knots_.begin()) - 1;
  // A knot at the horizon before t may be a step the horizon cut short; integration towards t
  // takes the whole step from the knot before.
  while (i > 0 && knots_[i].time == horizon_ && horizon_ < t) --i;
  return i;
}

void PlantMotion::input(Nanos t, plants::PlantInput which, bool level) {
  // Rewind to the plan's start and integrate to t: the same steps as the plan took, so the
  // history matches what the encoder played up to t. For a plant that resumes at its knots,
  // the steps up to the plan's last knot at or before t are the plan's own (the same advance()
  // calls from the same states): their segments and the state there are taken as they are,
  // and only the rest is integrated.
  const std::size_t from = resume_knot(t);
  for (std::size_t i = 1; i <= from; ++i)
    if (knots_[i].time > knots_[i - 1].time) history_.push_back(segment(knots_[i - 1], knots_[i]));
  if (live_ == nullptr)
    live_ = checkpoint_->clone();
  else
    live_->assign(*checkpoint_);
  if (from > 0) live_->resume_at(knots_[from]);
  const std::size_t before = checkpoint_->standstills().size();
  integrate(*live_, t, history_);
  const std::vector<Nanos>& located = live_->standstills();
  for (std::size_t i = before; i < located.size(); ++i) history_standstills_.push_back(located[i]);
  live_->input(which, level);
  plan_from(live_->state().angle * per_rad_);
}

void PlantMotion::extend() {
  if (live_ == nullptr || plan_end() >= end_) return;
  plan_all();
  for (const signals::Segment& s : plan_.segments()) history_.push_back(s);
  history_standstills_.insert(history_standstills_.end(), plan_standstills_.begin(), plan_standstills_.end());
  // On from the played plan's end position exactly (its segments chain in closed form, a
  // rounding away from the knots'): no jump where the shaft stands still.
  plan_from(plan_.end_position());
}

void PlantMotion::plan_from(double start) {
  const plants::Knot at = live_->state();
  checkpoint_->assign(*live_);
  knots_.clear();
  knots_.push_back(at);
  horizon_ = at.time < end_ - ahead_ ? at.time + ahead_ : end_;
  live_known_ = live_->standstills().size();
  plan_standstills_.clear();
  plan_.restart(start, at.time);
  // Nothing is integrated yet: the first look for an edge grows the plan (a stepper's next
  // pulse usually replaces it a few knots in, so knots integrated here ahead of that look
  // would mostly be thrown away).
}

// The knots integrate() would give on its way to the horizon, a few at a time: the same
// advance() calls, so the same segments.
bool PlantMotion::grow() const {
  plants::Knot prev = live_->state();
  if (prev.time >= horizon_) return false;
  for (int knots = 0; knots < kGrowKnots && prev.time < horizon_; ++knots) {
    const plants::Knot k = live_->advance(horizon_);
    if (k.time > prev.time) plan_.append(segment(prev, k));
    prev = k;
    if (keep_knots_) knots_.push_back(k);
  }
  const std::vector<Nanos>& located = live_->standstills();
  for (; live_known_ < located.size(); ++live_known_) plan_standstills_.push_back(located[live_known_]);
  return true;
}

void PlantMotion::plan_through(Nanos t) const {
  while (plan_.end_time() <= t && grow()) {}
}

// The segment of the history holding t (the last one starting at or before it; the history's
// segments are contiguous and in time order), or null when the plan holds it.
const signals::Segment* PlantMotion::history_at(Nanos t) const {
  if (history_.empty() || t >= plan_.start_time()) return nullptr;
  const auto after = std::upper_bound(history_.begin(), history_.end(), t,
                                      [](Nanos v, const signals::Segment& s) { return v < s.start; });
  return after == history_.begin() ? &history_.front() : &*std::prev(after);
}

double PlantMotion::position(Nanos t) const {
  plan_through(t);
  const signals::Segment* s = history_at(t);
  if (s == nullptr) return plan_.position(t);
  return t < s->start ? s->position : s->position_at(t);
}

double PlantMotion::velocity(Nanos t) const {
  plan_through(t);
  const signals::Segment* s = history_at(t);
  if (s == nullptr) return plan_.velocity(t);
  return t < s->start ? 0.0 : s->velocity_at(t);
}

signals::MotionProfile PlantMotion::trajectory() const {
  plan_all();
  const double start = history_.empty() ? plan_.position(plan_.start_time()) : history_.front().position;
  const Nanos t0 = history_.empty() ? plan_.start_time() : history_.front().start;
  signals::MotionProfile p(start, t0);
  p.reserve(history_.size() + plan_.segments().size());
  for (const signals::Segment& s : history_) p.append(s);
  for (const signals::Segment& s : plan_.segments()) p.append(s);
  return p;
}

signals::MotionProfile PlantMotion::take_trajectory() {
  plan_all();
  const double start = history_.empty() ? plan_.position(plan_.start_time()) : history_.front().position;
  const Nanos t0 = history_.empty() ? plan_.start_time() : history_.front().start;
  history_.insert(history_.end(), plan_.segments().begin(), plan_.segments().end());
  signals::MotionProfile whole = signals::MotionProfile::chained(start, t0, std::move(history_));
  history_.clear();
  return whole;
}

std::vector<checks::PositionSample> PlantMotion::samples() const {
  plan_all();
  std::vector<checks::PositionSample> out;
  const auto add = [&](const signals::Segment& s) { checks::append_motion(out, {s.start, s.position}); };
  for (const signals::Segment& s : history_) add(s);
  for (const signals::Segment& s : plan_.segments()) add(s);
  const signals::MotionProfile& last = plan_;
  checks::append_motion(out, {last.end_time(), last.end_position()});
  return out;
}

std::vector<Nanos> PlantMotion::standstills() const {
  plan_all();
  std::vector<Nanos> out = history_standstills_;
  out.insert(out.end(), plan_standstills_.begin(), plan_standstills_.end());
  return out;
}

} // namespace hilrig::campaign
