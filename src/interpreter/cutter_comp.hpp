// Cutter radius compensation C (G40/G41/G42 with D on a mill): the tool
// centre path from the programmed path, as a Fanuc-class control computes it.
//
// The interpreter emits the programmed path (machine coordinates, the
// programmed point of the tool); the compensator sits between the block and
// the motion side and turns it into the tool centre path. The end point of a
// compensated move depends on the move after it (the corner between them), so
// the compensator holds the last move of the offset plane back until the next
// one arrives, as the control reads ahead:
//   - start-up (G41/G42 from G40): the move goes from the programmed point to
//     the point offset perpendicular to the start of the next move (type A)
//     or, at an outer corner, to the intersection / the two extension
//     vectors (type B, parameter 5003#0 SUP = 1);
//   - offset mode: inner corners and outer corners of 90 degrees or more end
//     at the intersection of the two offset paths; outer corners under 90
//     degrees go round by the two vectors extended by the radius along each
//     move (the Fanuc "type C" corner: L, r, r, L);
//   - cancel (G40 with a move): the last compensated move ends perpendicular
//     to its end point (type A) or as at a start-up (type B), then the tool
//     goes to the programmed end point;
//   - a block without movement in the plane is looked past; two or more in a
//     row end the held move perpendicular to its end point, as the control
//     does (FANUC Series 16/18-C operator's manual, cutter compensation C,
//     "blocks without a move": the tool may overcut); so does a point where
//     the interpreter must wait for the machine (a live read, G31, M00, the
//     end of the program).
// Alarms: start-up or cancel in an arc (PS0034), no intersection at an inner
// corner (PS0033), a compensated move that runs against its programmed
// direction or an arc whose radius is used up by the offset (PS0041).
// docs/cutter-compensation.md has the rules with their sources and what is
// not simulated.
#pragma once

#include <optional>
#include <vector>

#include "canon/canon.hpp"
#include "core/diag.hpp"

namespace skipnc::interp::crc {

struct V2 {
  double x = 0.0;
  double y = 0.0;
};

// The compensation a block asks for, after its codes.
struct BlockMode {
  int side = 0;         // +1 G41 (tool left of the path), -1 G42, 0 G40
  double radius = 0.0;  // the D offset, mm; negative swaps the sides
  int a0 = 0;           // the offset plane's axes (G17: X Y, G18: Z X, G19: Y Z)
  int a1 = 1;
  bool type_b = false;       // start-up and cancel of type B (5003#0 SUP)
  bool suspend = false;      // G28 / G30 / G53: the block's moves are not offset
  int max_quiet_blocks = 1;  // blocks without a plane move looked past
};

class Compensator {
 public:
  // Nothing held and no offset vector: commands may bypass the compensator.
  bool idle() const noexcept { return !held_ && deferred_.empty() && !has_vector_; }
  // Starts tracking at the programmed (= tool) position `pos`.
  void begin(const AxisVec& pos) noexcept;
  // The commands of one block in order; `out` gets what can be sent now.
  // On failure nothing is changed only if the caller works on a copy (the
  // interpreter does: the block is a transaction).
  Result<void> block(const std::vector<canon::Stamped>& cmds, const BlockMode& mode,
                     std::vector<canon::Stamped>& out);
  // Sends what is held, the held move ending perpendicular to its end point.
  // Returns the line of that move (0: nothing was held).
  std::uint32_t flush(std::vector<canon::Stamped>& out);
  // The line of the move the last block() ended perpendicular because too
  // many blocks without a plane move followed it (0: none).
  std::uint32_t broke_lookahead() const noexcept { return broke_; }
  // Tool centre minus programmed point (plane axes; zero elsewhere), when
  // nothing is held (after flush()).
  AxisVec vector() const noexcept;

 private:
  struct Entity {
    canon::Stamped cmd;  // the programmed Rapid, Feed or Arc
    V2 p0, p1;           // programmed start and end on the plane
    bool arc = false;
    V2 c;  // arc centre
    bool ccw = false;
    double s = 0.0;  // signed offset: + left of the direction of travel
    bool startup = false;
    V2 start;  // where the tool starts this move (plane)
  };
  struct Corner {
    V2 end1;                  // where the first move ends
    std::vector<V2> inserts;  // lines after it
    V2 start2;                // where the second move starts
  };
  enum class Join { kNormal, kStartup, kCancel };

  Entity make(const canon::Stamped& cmd, const BlockMode& mode) const;
  Result<Corner> corner(const Entity& e1, const Entity& e2, Join join, bool type_b) const;
  struct Turn;  // the geometry of one corner (cutter_comp.cpp)
  static Turn turn(const Entity& e1, const Entity& e2, Join join);
  static void acute(const Turn& g, const Entity& e1, const Entity& e2, Join join, Corner& k);
  static Result<void> normal_corner(const Turn& g, const Entity& e1, const Entity& e2, Corner& k);
  // block(): one command; a move in the offset plane with G41/G42 or G40.
  Result<void> block_command(const canon::Stamped& c, const BlockMode& mode,
                             std::vector<canon::Stamped>& out, bool& plane_move);
  Result<void> offset_move(Entity e, const canon::Stamped& c, const BlockMode& mode,
                           std::vector<canon::Stamped>& out);
  Result<void> cancel_move(const Entity& e, const canon::Stamped& c, const BlockMode& mode,
                           std::vector<canon::Stamped>& out);
  // `check`: the interference check of a line (not for a flush, which
  // cannot refuse: what it holds must go out).
  Result<void> send_held(const Corner& k, const canon::Stamped* next_stamp,
                         std::vector<canon::Stamped>& out, bool check = true);
  Result<void> send_entity(const Entity& e, V2 end, std::vector<canon::Stamped>& out, bool check);
  void send_line(const canon::Stamped& like, V2 to, std::vector<canon::Stamped>& out);
  void send(canon::Stamped c, std::vector<canon::Stamped>& out);
  V2 plane(const AxisVec& v) const noexcept { return {v[a0_], v[a1_]}; }
  void set_plane(AxisVec& v, V2 p) const noexcept {
    v[a0_] = p.x;
    v[a1_] = p.y;
  }

  int a0_ = 0, a1_ = 1;
  AxisVec prog_;  // programmed end of the last move
  AxisVec tool_;  // tool centre at the end of what has been sent
  bool has_vector_ = false;
  std::optional<Entity> held_;
  std::vector<canon::Stamped> deferred_;  // commands after the held move
  int quiet_ = 0;                         // blocks without a plane move since it
  std::uint32_t broke_ = 0;
};

}  // namespace skipnc::interp::crc
