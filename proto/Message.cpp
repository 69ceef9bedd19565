#include "Message.hpp"

#include <cmath>

#include "TransportError.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

namespace fsi::proto {

namespace {

constexpr Eigen::Index values_per_point = 3;
constexpr std::size_t bytes_per_value = sizeof(double);

std::size_t checked_bytes(Eigen::Index n_points) {
  constexpr auto max_points = static_cast<Eigen::Index>(INT64_MAX / 64);
  if (n_points < 0 || n_points > max_points) {
    throw TransportError("cannot send an array of " + std::to_string(n_points) + " points");
  }
  return static_cast<std::size_t>(n_points * values_per_point) * bytes_per_value;
}

} // namespace

Message::Message(Envelope envelope) : envelope_(std::move(envelope)) {}

MutablePointsView Message::add_points(ArrayFrame &ref, Eigen::Index n_points) {
  const std::size_t n_bytes = checked_bytes(n_points);
  const auto owner = std::find(owners_.begin(), owners_.end(), &ref);
  std::size_t index = 0;
  if (owner != owners_.end()) {
    index = static_cast<std::size_t>(owner - owners_.begin());
    frames_[index]->rebuild(n_bytes);
  } else {
    index = frames_.size();
    frames_.push_back(std::make_unique<zmq::message_t>(n_bytes));
    owners_.push_back(&ref);
  }
  ref.set_frame(static_cast<std::uint32_t>(index + 1));
  ref.set_n_values(static_cast<std::uint64_t>(n_points * values_per_point));
  return MutablePointsView(n_points == 0 ? nullptr : static_cast<double *>(frames_[index]->data()), n_points,
                           values_per_point);
}

void Message::add_points(ArrayFrame &ref, const PointArray &points) { add_points(ref, points.rows()) = points; }

PointsView Message::points(const ArrayFrame &ref, std::string_view field_name) const {
  if (ref.frame() == 0) {
    return PointsView(nullptr, 0, values_per_point); // unset: no points
  }
  // The codec checked on receipt that ref names a frame of 8 n_values bytes.
  if (ref.frame() > frames_.size()) {
    throw MalformedMessageError(std::string(field_name) + " names array frame " + std::to_string(ref.frame()) +
                                " but the message has " + std::to_string(frames_.size()));
  }
  if (ref.n_values() % values_per_point != 0) {
    throw MalformedMessageError(std::string(field_name) + " holds " + std::to_string(ref.n_values()) +
                                " values, not a multiple of 3 (x y z per point)");
  }
  const auto &frame = *frames_[ref.frame() - 1];
  const auto n_points = static_cast<Eigen::Index>(ref.n_values() / values_per_point);
  return PointsView(n_points == 0 ? nullptr : static_cast<const double *>(frame.data()), n_points, values_per_point);
}

PointsView Message::points(const ArrayFrame &ref, Eigen::Index expected_n_points, std::string_view field_name) const {
  const PointsView view = points(ref, field_name);
  if (view.rows() != expected_n_points) {
    throw MalformedMessageError(std::string(field_name) + " holds " + std::to_string(ref.n_values()) +
                                " values, expected " + std::to_string(expected_n_points) + " points x 3");
  }
  return view;
}

PointsView Message::finite_points(const ArrayFrame &ref, Eigen::Index expected_n_points,
                                  std::string_view field_name) const {
  const PointsView view = points(ref, expected_n_points, field_name);
  if (view.allFinite())
    return view;
  for (Eigen::Index i = 0; i < view.rows(); ++i)
    for (Eigen::Index c = 0; c < view.cols(); ++c)
      if (!std::isfinite(view(i, c)))
        throw MalformedMessageError(std::string(field_name) + " holds " + std::to_string(view(i, c)) + " at point " +
                                    std::to_string(i) + " (" + "xyz"[c] + "): a value that is not finite");
  return view;
}

std::string_view Message::array_frame(std::size_t frame) const {
  const auto &bytes = *frames_.at(frame - 1);
  return {static_cast<const char *>(bytes.data()), bytes.size()};
}

} // namespace fsi::proto
