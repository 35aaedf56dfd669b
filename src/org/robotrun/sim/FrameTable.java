package org.robotrun.sim;

import java.util.Arrays;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;

/**
 * A controller's frames: tool frames UTOOL[1..10] (the TCP in the flange frame, {@code X_FT}) and
 * user frames UFRAME[1..10] (in WORLD, {@code X_WU}), each with a comment, plus the active
 * numbers. Number 0 is the flange (tool) or WORLD (user): identity, not editable. Mutable; one
 * per controller.
 */
public final class FrameTable {
  /** Highest frame number. */
  public static final int COUNT = 10;

  private final Transform[] tools = new Transform[COUNT + 1];
  private final Transform[] users = new Transform[COUNT + 1];
  private final String[] toolComments = new String[COUNT + 1];
  private final String[] userComments = new String[COUNT + 1];
  private int activeTool;
  private int activeUser;

  /** Every frame identity, no comments, UTOOL 0 and UFRAME 0 active. */
  public FrameTable() {
    Arrays.fill(tools, Transform.IDENTITY);
    Arrays.fill(users, Transform.IDENTITY);
    Arrays.fill(toolComments, "");
    Arrays.fill(userComments, "");
  }

  /** The frame's transform: {@code X_FT} for TOOL, {@code X_WU} for USER; number 0..10. */
  public Transform transform(FrameKind kind, int number) {
    check(number, 0);
    return kind == FrameKind.TOOL ? tools[number] : users[number];
  }

  /** Sets frame 1..10. */
  public void setTransform(FrameKind kind, int number, Transform value) {
    check(number, 1);
    if (kind == FrameKind.TOOL) {
      tools[number] = value;
    } else {
      users[number] = value;
    }
  }

  /** The frame as the pendant shows it (mm, deg), number 0..10. */
  public Position.Cartesian position(FrameKind kind, int number) {
    return Position.Cartesian.of(Xyzwpr.fromTransform(transform(kind, number)), Config.DEFAULT);
  }

  /** Sets frame 1..10 from pendant values (mm, deg; the configuration is ignored). */
  public void setPosition(FrameKind kind, int number, Position.Cartesian value) {
    setTransform(kind, number, value.toXyzwpr().toTransform());
  }

  public String comment(FrameKind kind, int number) {
    check(number, 0);
    return kind == FrameKind.TOOL ? toolComments[number] : userComments[number];
  }

  public void setComment(FrameKind kind, int number, String comment) {
    check(number, 1);
    (kind == FrameKind.TOOL ? toolComments : userComments)[number] = java.util.Objects.requireNonNull(comment);
  }

  /** The active UTOOL / UFRAME number, 0..10. */
  public int active(FrameKind kind) {
    return kind == FrameKind.TOOL ? activeTool : activeUser;
  }

  /** Selects the active UTOOL / UFRAME number, 0..10. */
  public void select(FrameKind kind, int number) {
    check(number, 0);
    if (kind == FrameKind.TOOL) {
      activeTool = number;
    } else {
      activeUser = number;
    }
  }

  /** The active tool's {@code X_FT}. */
  public Transform activeTool() {
    return tools[activeTool];
  }

  /** The active user frame's {@code X_WU}. */
  public Transform activeUser() {
    return users[activeUser];
  }

  // ---- jog frames (JOGFRAME[1..5], used only by the JGFRM jog coordinates) --------------------

  /** Jog frames a controller has: JOGFRAME[1..5]. */
  public static final int JOG_COUNT = 5;
  private final Transform[] jogFrames = filled(JOG_COUNT + 1);
  private int activeJog = 1;

  private static Transform[] filled(int n) {
    Transform[] t = new Transform[n];
    Arrays.fill(t, Transform.IDENTITY);
    return t;
  }

  private static void checkJog(int number) {
    if (number < 1 || number > JOG_COUNT) {
      throw new IllegalArgumentException("jog frame number must be 1.." + JOG_COUNT + ", got " + number);
    }
  }

  /** JOGFRAME[n] in WORLD ({@code X_WJ}), n = 1..5; WORLD until set. */
  public Position.Cartesian jogFrame(int number) {
    checkJog(number);
    return Position.Cartesian.of(Xyzwpr.fromTransform(jogFrames[number]), Config.DEFAULT);
  }

  /** Sets JOGFRAME[n] (mm, deg). */
  public void setJogFrame(int number, Position.Cartesian value) {
    checkJog(number);
    jogFrames[number] = value.toXyzwpr().toTransform();
  }

  /** The jog frame number JGFRM jogs in, 1..5. */
  public int activeJogNumber() {
    return activeJog;
  }

  public void selectJogFrame(int number) {
    checkJog(number);
    activeJog = number;
  }

  /** The active jog frame's {@code X_WJ}. */
  public Transform activeJogFrame() {
    return jogFrames[activeJog];
  }

  private static void check(int number, int lowest) {
    if (number < lowest || number > COUNT) {
      throw new IllegalArgumentException("frame number must be " + lowest + ".." + COUNT + ", got " + number);
    }
  }
}
