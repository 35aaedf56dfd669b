package org.robotrun.world;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.SortedMap;
import java.util.TreeMap;
import org.robotrun.math.Transform;

/**
 * A cell as an instructor ships it: robots, world objects and what to preload into each robot's
 * controller. All lengths mm, angles rad; files use degrees (see docs/scenario-format.md). Paths
 * are absolute here; files store them relative to themselves.
 *
 * <p>Every robot is equal: each {@link RobotSetup} carries its own programs, main program,
 * registers, frames, I/O sizes, macros and mode. The top-level {@code programs}, {@code
 * mainProgram}, {@code registers}, {@code frames} and {@code mode} of the file format are kept
 * here as the file has them (so a file is written back byte for byte) and are the first robot's:
 * {@link #preload(int)} is the one place that expands them, and every reader of a robot's
 * preload asks it.
 *
 * @param name a title for menus, may be empty
 * @param description what the exercise is about, may be empty
 * @param robots at least one
 * @param world the fixtures and parts
 * @param programs .LS files to load
 * @param mainProgram the program {@code robotrun run --scenario} runs when none is named
 * @param registers numeric registers R[i] to preset, by index
 * @param toolFrames tool frames UT[i] (pose of the TCP in the flange frame), by number
 * @param userFrames user frames UF[i] (pose in WORLD), by number
 * @param camera the initial view, if given
 * @param onCollision whether a collision stops the robot with an alarm or is only shown
 * @param mode the operator panel's mode switch when the window or a pendant script opens the
 *     cell: "T1", "T2" or "AUTO" (empty: T1, the window's default; {@code robotrun run} is AUTO)
 * @param wiring signals wired between robots and the cell (empty: none)
 * @param production production start from a PLC: UOP, PNS/RSR, background logic (empty: none)
 * @param vision cameras, vision processes and random part placement (empty: none)
 */
public record Scenario(
    String name,
    String description,
    List<RobotSetup> robots,
    World world,
    List<Path> programs,
    Optional<String> mainProgram,
    SortedMap<Integer, Double> registers,
    SortedMap<Integer, Transform> toolFrames,
    SortedMap<Integer, Transform> userFrames,
    Optional<CameraView> camera,
    CollisionResponse onCollision,
    Optional<String> mode,
    Wiring wiring,
    ProductionSetup production,
    VisionSetup vision) {

  /** The values {@code mode} may take. */
  public static final java.util.List<String> MODES = java.util.List.of("T1", "T2", "AUTO");

  public Scenario {
    robots = List.copyOf(robots);
    programs = programs.stream().map(p -> p.toAbsolutePath().normalize()).toList();
    registers = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(registers));
    toolFrames = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(toolFrames));
    userFrames = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(userFrames));
    if (robots.isEmpty()) {
      throw new IllegalArgumentException("a scenario needs at least one robot");
    }
    java.util.Objects.requireNonNull(onCollision, "onCollision");
    java.util.Objects.requireNonNull(wiring, "wiring");
    java.util.Objects.requireNonNull(production, "production");
    java.util.Objects.requireNonNull(vision, "vision");
    if (mode.isPresent() && !MODES.contains(mode.get())) {
      throw new IllegalArgumentException("mode must be one of " + MODES + ", got " + mode.get());
    }
  }

  /** A scenario with no wiring, production setup or vision. */
  public Scenario(String name, String description, List<RobotSetup> robots, World world, List<Path> programs,
      Optional<String> mainProgram, SortedMap<Integer, Double> registers, SortedMap<Integer, Transform> toolFrames,
      SortedMap<Integer, Transform> userFrames, Optional<CameraView> camera, CollisionResponse onCollision,
      Optional<String> mode) {
    this(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames, camera,
        onCollision, mode, Wiring.NONE, ProductionSetup.NONE, VisionSetup.NONE);
  }

  /** A scenario that leaves the mode switch at its default (T1). */
  public Scenario(String name, String description, List<RobotSetup> robots, World world, List<Path> programs,
      Optional<String> mainProgram, SortedMap<Integer, Double> registers, SortedMap<Integer, Transform> toolFrames,
      SortedMap<Integer, Transform> userFrames, Optional<CameraView> camera, CollisionResponse onCollision) {
    this(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames, camera,
        onCollision, Optional.empty());
  }

  /** A scenario whose collisions raise alarms. */
  public Scenario(String name, String description, List<RobotSetup> robots, World world, List<Path> programs,
      Optional<String> mainProgram, SortedMap<Integer, Double> registers, SortedMap<Integer, Transform> toolFrames,
      SortedMap<Integer, Transform> userFrames, Optional<CameraView> camera) {
    this(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames, camera,
        CollisionResponse.ALARM);
  }

  /**
   * What robot {@code i}'s controller starts with: its own programs, registers, frames and mode,
   * and for the first robot also the scenario's top-level ones (its programs first; the robot's
   * own main program before the scenario's; a register or frame given in both places: the
   * robot's).
   */
  public Preload preload(int i) {
    RobotSetup r = robots.get(i);
    if (i != 0) {
      return new Preload(r.programs(), r.mainProgram(), r.registers(), r.toolFrames(), r.userFrames(), r.mode().or(() -> mode));
    }
    List<Path> files = new java.util.ArrayList<>(programs);
    r.programs().stream().filter(p -> !files.contains(p)).forEach(files::add);
    TreeMap<Integer, Double> regs = new TreeMap<>(registers);
    regs.putAll(r.registers());
    TreeMap<Integer, Transform> tools = new TreeMap<>(toolFrames);
    tools.putAll(r.toolFrames());
    TreeMap<Integer, Transform> users = new TreeMap<>(userFrames);
    users.putAll(r.userFrames());
    return new Preload(files, r.mainProgram().or(() -> mainProgram), regs, tools, users, r.mode().or(() -> mode));
  }

  /**
   * One robot's preload (see {@link #preload(int)}).
   *
   * @param programs .LS files to load into its controller
   * @param mainProgram what {@code robotrun run --scenario} runs on it (empty: nothing, or
   *     {@code --program} on the first robot)
   * @param registers R[i] presets
   * @param toolFrames UT[i] presets (TCP in the flange frame)
   * @param userFrames UF[i] presets (in the robot's WORLD)
   * @param mode its mode switch when a window or pendant script opens the cell (empty: T1)
   */
  public record Preload(List<Path> programs, Optional<String> mainProgram, SortedMap<Integer, Double> registers,
      SortedMap<Integer, Transform> toolFrames, SortedMap<Integer, Transform> userFrames, Optional<String> mode) {
    public Preload {
      programs = List.copyOf(programs);
      registers = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(registers));
      toolFrames = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(toolFrames));
      userFrames = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(userFrames));
    }
  }

  /** This scenario under another name (and description). */
  public Scenario withName(String newName, String newDescription) {
    return new Scenario(newName, newDescription, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with other robots (their own presets with them). */
  public Scenario withRobots(List<RobotSetup> newRobots) {
    return new Scenario(name, description, newRobots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with another world (fixtures and parts). */
  public Scenario withWorld(World newWorld) {
    return new Scenario(name, description, robots, newWorld, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with another initial view. */
  public Scenario withCamera(Optional<CameraView> newCamera) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        newCamera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with other top-level programs and main program (the first robot's). */
  public Scenario withPrograms(List<Path> files, Optional<String> main) {
    return new Scenario(name, description, robots, world, files, main, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with other top-level register and frame presets (the first robot's). */
  public Scenario withPresets(SortedMap<Integer, Double> regs, SortedMap<Integer, Transform> tools,
      SortedMap<Integer, Transform> users) {
    return new Scenario(name, description, robots, world, programs, mainProgram, regs, tools, users,
        camera, onCollision, mode, wiring, production, vision);
  }

  /** This scenario with another mode switch (empty: T1). */
  public Scenario withMode(Optional<String> newMode) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, newMode, wiring, production, vision);
  }

  /** This scenario with {@code from}'s wiring, production setup and vision (a copy that changed other fields keeps them). */
  public Scenario withExtrasOf(Scenario from) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, from.wiring, from.production, from.vision);
  }

  /** This scenario with other wiring. */
  public Scenario withWiring(Wiring w) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, w, production, vision);
  }

  /** This scenario with another production setup. */
  public Scenario withProduction(ProductionSetup p) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, p, vision);
  }

  /** This scenario with another vision setup. */
  public Scenario withVision(VisionSetup v) {
    return new Scenario(name, description, robots, world, programs, mainProgram, registers, toolFrames, userFrames,
        camera, onCollision, mode, wiring, production, v);
  }
}
