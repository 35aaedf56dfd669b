package org.robotrun.world;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.SortedMap;
import java.util.TreeMap;
import org.robotrun.math.Transform;

/**
 * A cell as an instructor ships it: robots, world objects and what to preload into the
 * (first) robot's controller. All lengths mm, angles rad; files use degrees (see
 * docs/scenario-format.md). Paths are absolute here; files store them relative to themselves.
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
