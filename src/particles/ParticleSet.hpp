#pragma once
// Structure-of-arrays particle storage, templated on dimension. A field is
// allocated only when a scene asks for it (allocate(field::X{})); asking for an
// unallocated field is a logic error. Views taken from a set are invalid after
// resize(): take them again.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "kernels/Fields.hpp"

namespace ondine {

template <int D>
class ParticleSet {
 public:
  using Fields = std::tuple<field::Position, field::Velocity, field::Density, field::Pressure,
                            field::Mass, field::GlobalId, field::Acceleration, field::DensityRate,
                            field::DensityGradient, field::VelocityGradientX, field::VelocityGradientY,
                            field::VelocityGradientZ, field::ShepardGamma, field::FreeSurface,
                            field::TransportCorrection, field::MassRate, field::OpenRole,
                            field::EddyViscosity, field::FrictionVelocity, field::YPlus,
                            field::TurbulentKineticEnergy, field::DissipationRate, field::TurbulentKineticEnergyNext,
                            field::DissipationRateNext, field::MeanVelocity, field::LangevinVelocity,
                            field::LangevinOffset, field::LangevinDrift, field::LangevinGradientX, field::LangevinGradientY, field::LangevinGradientZ,
                            field::AprLevel, field::AprBirthLevel, field::AprGuard, field::AprMother, field::AprParent,
                            field::StagePosition, field::StageVelocity, field::StageDensity,
                            field::StagePositionSum, field::StageVelocitySum, field::StageDensitySum,
                            field::StageMass, field::StageMassSum,
                            field::LevelEndPosition, field::LevelEndVelocity, field::LevelEndDensity>;
  static constexpr int dimension = D;

  explicit ParticleSet(std::size_t n = 0) : n_(n) {}

  std::size_t size() const { return n_; }

  template <class Tag>
  bool has(Tag) const {
    return std::get<index<Tag>()>(views_).is_allocated();
  }

  template <class Tag>
  const field_view_t<Tag, D>& get(Tag) const {
    const auto& v = std::get<index<Tag>()>(views_);
    if (!v.is_allocated())
      throw std::logic_error(std::string("ondine: field '") + Tag::label + "' is not allocated");
    return v;
  }

  // Allocates (zero-filled) if absent; returns the view.
  template <class Tag>
  const field_view_t<Tag, D>& allocate(Tag) {
    auto& v = std::get<index<Tag>()>(views_);
    if (!v.is_allocated()) v = field_view_t<Tag, D>(std::string("ondine::particles::") + Tag::label, n_);
    return v;
  }

  // Changes the particle count, keeping the first min(n, size()) entries of every allocated field.
  void resize(std::size_t n) {
    n_ = n;
    for_each_view([n](auto, auto& v) {
      if (v.is_allocated()) Kokkos::resize(v, n);
    });
  }

  // Replaces every allocated field v by f(v) (same type), e.g. a reordering or
  // a compaction to `new_size` particles.
  template <class F>
  void permute(F&& f, std::size_t new_size) {
    n_ = new_size;
    permute(std::forward<F>(f));
  }
  template <class F>
  void permute(F&& f) {
    for_each_view([&f](auto, auto& v) {
      if (v.is_allocated()) v = f(v);
    });
  }

  // f(tag, view) for every allocated field, in declaration order.
  template <class F>
  void for_each_allocated(F&& f) const {
    const_cast<ParticleSet*>(this)->for_each_view([&f](auto tag, auto& v) {
      if (v.is_allocated()) f(tag, static_cast<const std::decay_t<decltype(v)>&>(v));
    });
  }

  std::vector<std::string> allocated_labels() const {
    std::vector<std::string> out;
    for_each_allocated([&out](auto tag, const auto&) { out.emplace_back(decltype(tag)::label); });
    return out;
  }

 private:
  template <class Tag, std::size_t I = 0>
  static constexpr std::size_t index() {
    static_assert(I < std::tuple_size<Fields>::value, "field is not part of ParticleSet::Fields");
    if constexpr (std::is_same<Tag, std::tuple_element_t<I, Fields>>::value)
      return I;
    else
      return index<Tag, I + 1>();
  }

  template <class F>
  void for_each_view(F&& f) {
    for_each_view_impl(std::forward<F>(f), std::make_index_sequence<std::tuple_size<Fields>::value>{});
  }
  template <class F, std::size_t... I>
  void for_each_view_impl(F&& f, std::index_sequence<I...>) {
    (f(std::tuple_element_t<I, Fields>{}, std::get<I>(views_)), ...);
  }

  template <class Tuple>
  struct ViewsOf;
  template <class... Tags>
  struct ViewsOf<std::tuple<Tags...>> {
    using type = std::tuple<field_view_t<Tags, D>...>;
  };

  std::size_t n_;
  typename ViewsOf<Fields>::type views_;
};

}  // namespace ondine
