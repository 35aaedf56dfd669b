package org.robotrun.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * The solid parts of an end effector, in the flange frame F (z out of the flange, mm): where its
 * TCP is, its collision boxes, and for grippers and suction cups the zone a part must overlap
 * to be picked. All tools are straight along the flange's z axis; the numbers are those of the
 * examples' tools, not of a catalogue model.
 *
 * <ul>
 *   <li><b>faceplate</b>: nothing on the flange; TCP = flange.
 *   <li><b>gripper</b>: a 50 × 100 × 68 mm body, two 20 × 10 × 50 mm fingers moving along the
 *       flange's y axis (70 mm apart open, closing to touch), TCP between the finger tips,
 *       120 mm out.
 *   <li><b>suction</b>: a 30 mm stem and a 44 mm cup; TCP on the cup's face, 110 mm out. The
 *       cup's collision box stops 1 mm short of the face, so the cup can sit on a part.
 *   <li><b>pointer</b>: a 30 mm holder and an 8 mm rod ending in a point; TCP at the point,
 *       150 mm out. The rod's box stops 2 mm short of the point, so the point can touch a
 *       marker without a collision alarm.
 *   <li><b>gluegun</b>: a 60 mm body and a 10 mm nozzle; TCP at the nozzle tip, 140 mm out,
 *       the nozzle's box 2 mm short of it.
 * </ul>
 *
 * @param type which tool
 * @param X_FT the TCP in the flange frame (the default tool frame)
 * @param bodyBoxes the boxes that never move relative to the flange
 * @param pickupZone where a part must be to be picked (grippers and suction cups)
 */
public record EndEffectorGeometry(EndEffectorType type, Transform X_FT, List<LocalBox> bodyBoxes,
    Optional<LocalBox> pickupZone) {

  /** Gap between the flange and a tool's first box, so a tool never touches its own wrist (mm). */
  public static final double FLANGE_GAP_MM = 2;

  // Gripper (mm): body, fingers, opening.
  public static final double GRIPPER_TCP_MM = 120;
  public static final double GRIPPER_BODY_X_MM = 50;
  public static final double GRIPPER_BODY_Y_MM = 100;
  public static final double GRIPPER_BODY_END_MM = 70;
  public static final double FINGER_X_MM = 20;
  public static final double FINGER_Y_MM = 10;
  public static final double FINGER_OPEN_GAP_MM = 70;

  // Suction (mm).
  public static final double SUCTION_TCP_MM = 110;
  public static final double SUCTION_STEM_RADIUS_MM = 15;
  public static final double SUCTION_CUP_RADIUS_MM = 22;
  public static final double SUCTION_CUP_START_MM = 90;
  public static final double SUCTION_CLEARANCE_MM = 1;

  // Pointer (mm).
  public static final double POINTER_TCP_MM = 150;
  public static final double POINTER_HOLDER_RADIUS_MM = 15;
  public static final double POINTER_HOLDER_END_MM = 60;
  public static final double POINTER_ROD_RADIUS_MM = 4;
  public static final double POINTER_TIP_CLEARANCE_MM = 2;

  // Glue gun (mm).
  public static final double GLUE_TCP_MM = 140;
  public static final double GLUE_BODY_MM = 60;
  public static final double GLUE_BODY_END_MM = 95;
  public static final double GLUE_NOZZLE_RADIUS_MM = 5;
  public static final double GLUE_TIP_CLEARANCE_MM = 2;

  public EndEffectorGeometry {
    bodyBoxes = List.copyOf(bodyBoxes);
  }

  /** The standard tool of a type, as described above. */
  public static EndEffectorGeometry of(EndEffectorType type) {
    return switch (type) {
      case FACEPLATE -> new EndEffectorGeometry(type, Transform.IDENTITY, List.of(), Optional.empty());
      case GRIPPER -> new EndEffectorGeometry(type, Transform.translation(0, 0, GRIPPER_TCP_MM),
          List.of(span(GRIPPER_BODY_X_MM / 2, GRIPPER_BODY_Y_MM / 2, FLANGE_GAP_MM, GRIPPER_BODY_END_MM)),
          // Between the fingers, over their lower 30 mm: a part sticking into it is picked.
          Optional.of(span(FINGER_X_MM / 2, FINGER_OPEN_GAP_MM / 2, GRIPPER_TCP_MM - 30, GRIPPER_TCP_MM)));
      case SUCTION -> {
        double face = SUCTION_TCP_MM - SUCTION_CLEARANCE_MM;
        yield new EndEffectorGeometry(type, Transform.translation(0, 0, SUCTION_TCP_MM),
            List.of(span(SUCTION_STEM_RADIUS_MM, SUCTION_STEM_RADIUS_MM, FLANGE_GAP_MM, SUCTION_CUP_START_MM),
                span(SUCTION_CUP_RADIUS_MM, SUCTION_CUP_RADIUS_MM, SUCTION_CUP_START_MM, face)),
            // From just inside the cup to 3 mm beyond the face: the cup must sit on (or in) the part.
            Optional.of(span(SUCTION_STEM_RADIUS_MM, SUCTION_STEM_RADIUS_MM, face - 1, SUCTION_TCP_MM + 3)));
      }
      case POINTER -> new EndEffectorGeometry(type, Transform.translation(0, 0, POINTER_TCP_MM),
          List.of(span(POINTER_HOLDER_RADIUS_MM, POINTER_HOLDER_RADIUS_MM, FLANGE_GAP_MM, POINTER_HOLDER_END_MM),
              span(POINTER_ROD_RADIUS_MM, POINTER_ROD_RADIUS_MM, POINTER_HOLDER_END_MM,
                  POINTER_TCP_MM - POINTER_TIP_CLEARANCE_MM)),
          Optional.empty());
      case GLUEGUN -> new EndEffectorGeometry(type, Transform.translation(0, 0, GLUE_TCP_MM),
          List.of(span(GLUE_BODY_MM / 2, GLUE_BODY_MM / 2, FLANGE_GAP_MM, GLUE_BODY_END_MM),
              span(GLUE_NOZZLE_RADIUS_MM, GLUE_NOZZLE_RADIUS_MM, GLUE_BODY_END_MM, GLUE_TCP_MM - GLUE_TIP_CLEARANCE_MM)),
          Optional.empty());
    };
  }

  /** Whether switching the tool on picks up a part (gripper, suction cup). */
  public boolean picksParts() {
    return pickupZone.isPresent();
  }

  /** Whether the tool leaves a trace while on (glue gun). */
  public boolean leavesTrace() {
    return type == EndEffectorType.GLUEGUN;
  }

  /** Whether the tool has fingers that open and close. */
  public boolean hasFingers() {
    return type == EndEffectorType.GRIPPER;
  }

  /**
   * The finger boxes (flange frame) with the inner faces {@code gapMm} apart along y; empty
   * for tools without fingers.
   */
  public List<LocalBox> fingerBoxes(double gapMm) {
    if (!hasFingers()) {
      return List.of();
    }
    List<LocalBox> out = new ArrayList<>(2);
    double cy = gapMm / 2 + FINGER_Y_MM / 2;
    double zc = (GRIPPER_BODY_END_MM + GRIPPER_TCP_MM) / 2;
    double hz = (GRIPPER_TCP_MM - GRIPPER_BODY_END_MM) / 2;
    out.add(new LocalBox(Transform.translation(0, -cy, zc), FINGER_X_MM / 2, FINGER_Y_MM / 2, hz));
    out.add(new LocalBox(Transform.translation(0, cy, zc), FINGER_X_MM / 2, FINGER_Y_MM / 2, hz));
    return out;
  }

  /** Every collision box with the fingers {@code gapMm} apart: the body first, then the fingers. */
  public List<LocalBox> boxes(double gapMm) {
    List<LocalBox> out = new ArrayList<>(bodyBoxes);
    out.addAll(fingerBoxes(gapMm));
    return out;
  }

  /** Names of the boxes of {@link #boxes}, in the same order ("body", "finger1", …). */
  public List<String> boxNames() {
    return switch (type) {
      case FACEPLATE -> List.of();
      case GRIPPER -> List.of("body", "finger1", "finger2");
      case SUCTION -> List.of("stem", "cup");
      case POINTER -> List.of("holder", "rod");
      case GLUEGUN -> List.of("body", "nozzle");
    };
  }

  /** A box with half widths {@code hx}, {@code hy} from {@code z0} to {@code z1} along the flange's z. */
  private static LocalBox span(double hx, double hy, double z0, double z1) {
    return new LocalBox(Transform.translation(0, 0, (z0 + z1) / 2), hx, hy, (z1 - z0) / 2);
  }
}
