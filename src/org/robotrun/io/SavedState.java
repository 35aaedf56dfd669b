package org.robotrun.io;

import java.util.Collections;
import java.util.Map;
import java.util.Objects;
import java.util.SortedMap;
import java.util.TreeMap;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Registers;
import org.robotrun.sim.Controller;
import org.robotrun.sim.FrameTable;

/**
 * What a workspace keeps of the first robot's controller beyond what a scenario already holds
 * (joints, frames, objects, camera): the {@code "state"} section of {@code cell.json}
 * (docs/scenario-format.md). Values are the pendant's (mm, degrees).
 *
 * @param overridePct the speed override, 1..100, or -1 when not saved (the controller's default stays)
 * @param activeTool the active UTOOL number, 0..10, or -1 when not saved (the cell's choice stays)
 * @param activeUser the active UFRAME number, 0..10, or -1 when not saved
 * @param registers R[i] that are not integer 0, by index
 * @param positionRegisters PR[i] that are not the Cartesian zero, by index
 * @param outputs non-zero outputs and flags, keyed {@code "DO[3]"}, {@code "GO[1]"}, {@code "F[2]"}
 * @param comments item comments, keyed {@code "R[1]"}, {@code "PR[2]"}, {@code "UT[1]"}, {@code "UF[3]"}
 * @param created when the workspace was made (ISO-8601 UTC), may be empty
 * @param toolFrames UT[i] as the pendant shows them, for a robot after the first (the first's are
 *     the scenario's "frames"); empty for the first
 * @param userFrames UF[i] likewise
 * @param robots the state of every robot after the first, by name (a cell of several robots)
 * @param stringRegisters SR[i] that are not empty text, by index
 */
public record SavedState(
    int overridePct,
    int activeTool,
    int activeUser,
    SortedMap<Integer, Register> registers,
    SortedMap<Integer, Position> positionRegisters,
    SortedMap<String, Integer> outputs,
    SortedMap<String, String> comments,
    String created,
    SortedMap<Integer, Position> toolFrames,
    SortedMap<Integer, Position> userFrames,
    SortedMap<String, SavedState> robots,
    SortedMap<Integer, String> stringRegisters) {

  /** A data register's value and whether it holds an integer (FANUC keeps the two apart). */
  public record Register(double value, boolean integer) {}

  public SavedState {
    registers = Collections.unmodifiableSortedMap(new TreeMap<>(registers));
    positionRegisters = Collections.unmodifiableSortedMap(new TreeMap<>(positionRegisters));
    outputs = Collections.unmodifiableSortedMap(new TreeMap<>(outputs));
    comments = Collections.unmodifiableSortedMap(new TreeMap<>(comments));
    Objects.requireNonNull(created, "created");
    toolFrames = Collections.unmodifiableSortedMap(new TreeMap<>(toolFrames));
    userFrames = Collections.unmodifiableSortedMap(new TreeMap<>(userFrames));
    robots = Collections.unmodifiableSortedMap(new TreeMap<>(robots));
    stringRegisters = Collections.unmodifiableSortedMap(new TreeMap<>(stringRegisters));
  }

  /** A state with no SR[] values. */
  public SavedState(int overridePct, int activeTool, int activeUser, SortedMap<Integer, Register> registers,
      SortedMap<Integer, Position> positionRegisters, SortedMap<String, Integer> outputs, SortedMap<String, String> comments,
      String created, SortedMap<Integer, Position> toolFrames, SortedMap<Integer, Position> userFrames,
      SortedMap<String, SavedState> robots) {
    this(overridePct, activeTool, activeUser, registers, positionRegisters, outputs, comments, created, toolFrames,
        userFrames, robots, new TreeMap<>());
  }

  /** One robot's state with no frames of its own and no other robots. */
  public SavedState(int overridePct, int activeTool, int activeUser, SortedMap<Integer, Register> registers,
      SortedMap<Integer, Position> positionRegisters, SortedMap<String, Integer> outputs, SortedMap<String, String> comments,
      String created) {
    this(overridePct, activeTool, activeUser, registers, positionRegisters, outputs, comments, created, new TreeMap<>(),
        new TreeMap<>(), new TreeMap<>());
  }

  /**
   * The state of a whole cell now: the first controller's as {@link #capture}, and every other
   * robot's (with its tool and user frames, which the scenario does not hold) under {@code robots}.
   */
  public static SavedState captureCell(java.util.List<Controller> controllers, String created) {
    SavedState first = capture(controllers.get(0), created);
    SortedMap<String, SavedState> others = new TreeMap<>();
    for (int i = 1; i < controllers.size(); i++) {
      Controller c = controllers.get(i);
      SavedState s = capture(c, "");
      SortedMap<Integer, Position> ut = new TreeMap<>();
      SortedMap<Integer, Position> uf = new TreeMap<>();
      for (int n = 1; n <= FrameTable.COUNT; n++) {
        if (!c.frames().transform(FrameKind.TOOL, n).equals(org.robotrun.math.Transform.IDENTITY)) {
          ut.put(n, c.frame(FrameKind.TOOL, n));
        }
        if (!c.frames().transform(FrameKind.USER, n).equals(org.robotrun.math.Transform.IDENTITY)) {
          uf.put(n, c.frame(FrameKind.USER, n));
        }
      }
      others.put(c.name(), new SavedState(s.overridePct, s.activeTool, s.activeUser, s.registers, s.positionRegisters,
          s.outputs, s.comments, "", ut, uf, new TreeMap<>(), s.stringRegisters));
    }
    return new SavedState(first.overridePct, first.activeTool, first.activeUser, first.registers, first.positionRegisters,
        first.outputs, first.comments, created, new TreeMap<>(), new TreeMap<>(), others, first.stringRegisters);
  }

  /**
   * Puts this state into a cell: the first controller gets this state, every other the state
   * saved under its name (a robot saved under a name the cell no longer has is left out).
   */
  public void applyToCell(java.util.List<Controller> controllers) {
    applyTo(controllers.get(0));
    for (int i = 1; i < controllers.size(); i++) {
      SavedState s = robots.get(controllers.get(i).name());
      if (s != null) {
        s.applyTo(controllers.get(i));
      }
    }
  }

  /** A new workspace's state: nothing saved yet but its creation time. */
  public static SavedState fresh(String created) {
    return new SavedState(-1, -1, -1, new TreeMap<>(), new TreeMap<>(), new TreeMap<>(), new TreeMap<>(), created);
  }

  /** The state of {@code c} now. */
  public static SavedState capture(Controller c, String created) {
    Registers regs = c.registers();
    SortedMap<Integer, Register> r = new TreeMap<>();
    for (int i = 1; i <= Registers.R_COUNT; i++) {
      if (regs.number(i) != 0 || !regs.isInteger(i)) {
        r.put(i, new Register(regs.number(i), regs.isInteger(i)));
      }
    }
    SortedMap<Integer, Position> pr = new TreeMap<>();
    for (int i = 1; i <= Registers.PR_COUNT; i++) {
      if (!regs.position(i).equals(Position.Cartesian.ZERO)) {
        pr.put(i, regs.position(i));
      }
    }
    SortedMap<String, Integer> out = new TreeMap<>();
    for (IoKind k : IoKind.values()) {
      if (!k.writable()) {
        continue;  // inputs come from the cell, not from the student
      }
      for (int i = 1; i <= regs.ioSize(k); i++) {
        if (regs.value(k, i) != 0) {
          out.put(k.name() + "[" + i + "]", regs.value(k, i));
        }
      }
    }
    SortedMap<String, String> comments = new TreeMap<>();
    for (int i = 1; i <= Registers.R_COUNT; i++) {
      putComment(comments, "R[" + i + "]", c.registerComment("R", i));
    }
    for (int i = 1; i <= Registers.PR_COUNT; i++) {
      putComment(comments, "PR[" + i + "]", c.registerComment("PR", i));
    }
    for (int i = 1; i <= FrameTable.COUNT; i++) {
      putComment(comments, "UT[" + i + "]", c.frames().comment(FrameKind.TOOL, i));
      putComment(comments, "UF[" + i + "]", c.frames().comment(FrameKind.USER, i));
    }
    SortedMap<Integer, String> sr = new TreeMap<>();
    for (int i = 1; i <= Registers.SR_COUNT; i++) {
      if (!regs.string(i).isEmpty()) {
        sr.put(i, regs.string(i));
      }
    }
    return new SavedState(c.overridePct(), c.frames().active(FrameKind.TOOL), c.frames().active(FrameKind.USER),
        r, pr, out, comments, created, new TreeMap<>(), new TreeMap<>(), new TreeMap<>(), sr);
  }

  private static void putComment(Map<String, String> comments, String key, String text) {
    if (!text.isEmpty()) {
      comments.put(key, text);
    }
  }

  /**
   * Puts this state into {@code c}: override, active frames, registers, outputs and comments.
   * Keys were checked when the file was read.
   */
  public void applyTo(Controller c) {
    // Frames first: selecting a frame number is checked against the table.
    toolFrames.forEach((n, p) -> c.setFrame(FrameKind.TOOL, n, (Position.Cartesian) p));
    userFrames.forEach((n, p) -> c.setFrame(FrameKind.USER, n, (Position.Cartesian) p));
    if (overridePct > 0) {
      c.setOverridePct(overridePct);
    }
    if (activeTool >= 0) {
      c.frames().select(FrameKind.TOOL, activeTool);
    }
    if (activeUser >= 0) {
      c.frames().select(FrameKind.USER, activeUser);
    }
    registers.forEach((i, v) -> c.registers().set(i, v.value(), v.integer()));
    positionRegisters.forEach(c.registers()::setPosition);
    stringRegisters.forEach(c.registers()::setString);
    outputs.forEach((key, v) -> {
      Item item = Item.parse(key);
      IoKind kind = IoKind.valueOf(item.table());
      // A port beyond this robot's configured I/O (the cell's "io" was made smaller) has no value to restore.
      if (item.index() <= c.registers().ioSize(kind)) {
        c.registers().setValue(kind, item.index(), v);
      }
    });
    comments.forEach((key, text) -> {
      Item item = Item.parse(key);
      switch (item.table()) {
        case "UT" -> c.frames().setComment(FrameKind.TOOL, item.index(), text);
        case "UF" -> c.frames().setComment(FrameKind.USER, item.index(), text);
        default -> c.setRegisterComment(item.table(), item.index(), text);
      }
    });
  }

  /** {@code "DO[3]"} as table and index; null when the text is not of that form. */
  record Item(String table, int index) {
    static Item parse(String key) {
      int open = key.indexOf('[');
      if (open <= 0 || !key.endsWith("]")) {
        return null;
      }
      try {
        return new Item(key.substring(0, open), Integer.parseInt(key.substring(open + 1, key.length() - 1)));
      } catch (NumberFormatException e) {
        return null;
      }
    }
  }
}
