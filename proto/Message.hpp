#pragma once
// One message of the coupling protocol as both sides hold it: the Envelope (the header, small)
// and the frames of its large arrays, which its ArrayFrame fields name. An array is written in
// place into the frame that will travel (add_points) and read in place from the frame that
// arrived (points): neither serialised nor parsed, and not copied beyond the socket's own copy.
//
//   Message reply(make_envelope(role, step));
//   auto *body = reply.envelope().mutable_advance_reply();     // the body first,
//   reply.add_points(*body->mutable_position_m(), n) = x;     // then its arrays
//   session.send(reply);                                       // the frames go, the header stays

#include "PackedPoints.hpp"
#include "Protocol.hpp"

#include <zmq.hpp>

#include <memory>
#include <string_view>
#include <vector>

namespace fsi::proto {

using ArrayFrame = v2::ArrayFrame;

class Message {
public:
  Message() = default;
  /// A message with this header and no arrays yet (Hello, Heartbeat, ... need none).
  Message(Envelope envelope); // NOLINT(google-explicit-constructor): every Envelope is a message
  Message(Message &&) noexcept = default;
  Message &operator=(Message &&) noexcept = default;
  Message(const Message &) = delete; // the frames are not copied
  Message &operator=(const Message &) = delete;

  Envelope &envelope() { return envelope_; }
  const Envelope &envelope() const { return envelope_; }

  /// A frame of n_points x 3 doubles for the field `ref` of this message's envelope, which it
  /// sets to name the frame; returns a view to fill (values undefined), valid until the message
  /// is sent. Adding to the same field again before sending replaces its frame. Set the body
  /// first: a field of a body that is replaced afterwards leaves a dangling frame.
  MutablePointsView add_points(ArrayFrame &ref, Eigen::Index n_points);
  /// As above, filled with a copy of points.
  void add_points(ArrayFrame &ref, const PointArray &points);

  /// The array a received message's field names, as n x 3 points without copying; valid until
  /// the next message is received into this one. Throws MalformedMessageError naming
  /// field_name when the field is unset (only with an expected count above 0), holds a number
  /// of values that is not a multiple of 3, or not expected_n_points points.
  PointsView points(const ArrayFrame &ref, std::string_view field_name) const;
  PointsView points(const ArrayFrame &ref, Eigen::Index expected_n_points, std::string_view field_name) const;
  /// As points(ref, expected_n_points, field_name), and throws MalformedMessageError naming the
  /// first point and component that is NaN or infinite: state a receiver keeps must be finite.
  PointsView finite_points(const ArrayFrame &ref, Eigen::Index expected_n_points, std::string_view field_name) const;

  /// Array frames held: added and not yet sent, or received.
  std::size_t array_frame_count() const { return frames_.size(); }
  /// The bytes of an array frame, numbered as ArrayFrame.frame (from 1); throws std::out_of_range.
  std::string_view array_frame(std::size_t frame) const;

private:
  friend class EnvelopeCodec;

  Envelope envelope_;
  // Each frame on the heap: adding a frame never moves the others, so the views handed out stay
  // valid (a small frame keeps its bytes inside the zmq::message_t itself).
  std::vector<std::unique_ptr<zmq::message_t>> frames_;
  std::vector<const ArrayFrame *> owners_; ///< the field each added frame belongs to
};

} // namespace fsi::proto
