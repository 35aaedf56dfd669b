package org.robotrun.world;

import java.util.List;
import org.robotrun.math.Transform;

/**
 * A robot placed in a cell.
 *
 * @param name unique in the scenario, used in alarms ("robot1")
 * @param modelId the robot definition, e.g. "lrmate200id"
 * @param X_CB the robot's base frame (on its mounting plate, on the J1 axis) in the cell (mm)
 * @param endEffector the tool on its flange
 * @param initialJointsRad six joint values in the pendant's convention (FANUC coupled J3), rad
 * @param toolIo the I/O ports the end effector uses
 * @param io the controller's I/O sizes that differ from its defaults, by kind ("DO" → 1024); the
 *     names and bounds are checked by the reader and the controller (program.IoRanges)
 * @param userAlarms the UALM[i] texts of the controller ($UALRM_MSG[i]), by number
 * @param programs .LS files loaded into this robot's controller only (absolute paths; the
 *     scenario-level programs go to the first robot)
 * @param mainProgram the program {@code robotrun run --scenario} runs on this robot (empty: the
 *     first robot runs the scenario's main program, another robot runs nothing)
 * @param macros the controller's macro table (MENU &gt; SETUP &gt; Macro), in its order: each
 *     macro name and the program it runs
 * @param registers numeric registers R[i] to preset in this robot's controller, by index (the
 *     first robot also gets the scenario's top-level {@code "registers"}: {@link Scenario#preload})
 * @param toolFrames tool frames UT[i] to preset (pose of the TCP in the flange frame), by number
 * @param userFrames user frames UF[i] to preset (pose in the robot's WORLD), by number
 * @param mode this robot's mode switch when a window or pendant script opens the cell ("T1",
 *     "T2", "AUTO"; empty: the scenario's {@code "mode"})
 */
public record RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad,
    ToolIo toolIo, java.util.SortedMap<String, Integer> io, java.util.SortedMap<Integer, String> userAlarms,
    List<java.nio.file.Path> programs, java.util.Optional<String> mainProgram, List<Macro> macros,
    java.util.SortedMap<Integer, Double> registers, java.util.SortedMap<Integer, Transform> toolFrames,
    java.util.SortedMap<Integer, Transform> userFrames, java.util.Optional<String> mode) {

  /** One row of the macro table: a macro name ("HAND1 OPEN") and the program it runs ("HOPEN"). */
  public record Macro(String name, String program) {
    public Macro {
      java.util.Objects.requireNonNull(name, "name");
      java.util.Objects.requireNonNull(program, "program");
    }
  }

  /** A robot with no presets of its own (registers, frames, mode). */
  public RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad,
      ToolIo toolIo, java.util.SortedMap<String, Integer> io, java.util.SortedMap<Integer, String> userAlarms,
      List<java.nio.file.Path> programs, java.util.Optional<String> mainProgram, List<Macro> macros) {
    this(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, programs, mainProgram, macros,
        new java.util.TreeMap<>(), new java.util.TreeMap<>(), new java.util.TreeMap<>(), java.util.Optional.empty());
  }

  /** A robot with an empty macro table. */
  public RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad,
      ToolIo toolIo, java.util.SortedMap<String, Integer> io, java.util.SortedMap<Integer, String> userAlarms,
      List<java.nio.file.Path> programs, java.util.Optional<String> mainProgram) {
    this(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, programs, mainProgram, List.of());
  }

  public RobotSetup {
    macros = List.copyOf(macros);
    java.util.Objects.requireNonNull(toolIo, "toolIo");
    java.util.Objects.requireNonNull(mainProgram, "mainProgram");
    programs = programs.stream().map(p -> p.toAbsolutePath().normalize()).toList();
    io = java.util.Collections.unmodifiableSortedMap(new java.util.TreeMap<>(io));
    userAlarms = java.util.Collections.unmodifiableSortedMap(new java.util.TreeMap<>(userAlarms));
    initialJointsRad = List.copyOf(initialJointsRad);
    registers = java.util.Collections.unmodifiableSortedMap(new java.util.TreeMap<>(registers));
    toolFrames = java.util.Collections.unmodifiableSortedMap(new java.util.TreeMap<>(toolFrames));
    userFrames = java.util.Collections.unmodifiableSortedMap(new java.util.TreeMap<>(userFrames));
    java.util.Objects.requireNonNull(mode, "mode");
    if (mode.isPresent() && !Scenario.MODES.contains(mode.get())) {
      throw new IllegalArgumentException("mode must be one of " + Scenario.MODES + ", got " + mode.get());
    }
    if (initialJointsRad.size() != 6) {
      throw new IllegalArgumentException("a robot needs 6 initial joint values, got " + initialJointsRad.size());
    }
  }

  /** A robot with no programs of its own. */
  public RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad,
      ToolIo toolIo, java.util.SortedMap<String, Integer> io, java.util.SortedMap<Integer, String> userAlarms) {
    this(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, List.of(), java.util.Optional.empty());
  }

  /** This robot standing at other initial joints (rad, pendant convention); everything else kept. */
  public RobotSetup withJoints(List<Double> jointsRad) {
    return new RobotSetup(name, modelId, X_CB, endEffector, jointsRad, toolIo, io, userAlarms, programs, mainProgram, macros,
        registers, toolFrames, userFrames, mode);
  }

  /** This robot with other programs of its own and main program. */
  public RobotSetup withPrograms(List<java.nio.file.Path> files, java.util.Optional<String> main) {
    return new RobotSetup(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, files, main, macros,
        registers, toolFrames, userFrames, mode);
  }

  /** This robot with another macro table. */
  public RobotSetup withMacros(List<Macro> table) {
    return new RobotSetup(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, programs, mainProgram, table,
        registers, toolFrames, userFrames, mode);
  }

  /** This robot with other register and frame presets of its own. */
  public RobotSetup withPresets(java.util.SortedMap<Integer, Double> regs, java.util.SortedMap<Integer, Transform> tools,
      java.util.SortedMap<Integer, Transform> users) {
    return new RobotSetup(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, programs, mainProgram,
        macros, regs, tools, users, mode);
  }

  /** This robot with its own mode switch (empty: the scenario's). */
  public RobotSetup withMode(java.util.Optional<String> m) {
    return new RobotSetup(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, io, userAlarms, programs, mainProgram,
        macros, registers, toolFrames, userFrames, m);
  }

  /** A robot with the controller's default I/O sizes and no UALM texts. */
  public RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad,
      ToolIo toolIo) {
    this(name, modelId, X_CB, endEffector, initialJointsRad, toolIo, new java.util.TreeMap<>(), new java.util.TreeMap<>());
  }

  /** A robot whose end effector uses {@link ToolIo#DEFAULT} (RO[1], RI[1], RI[2]). */
  public RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad) {
    this(name, modelId, X_CB, endEffector, initialJointsRad, ToolIo.DEFAULT);
  }

  /** The initial joints as an array (rad, pendant convention). */
  public double[] initialJoints() {
    return initialJointsRad.stream().mapToDouble(Double::doubleValue).toArray();
  }
}
