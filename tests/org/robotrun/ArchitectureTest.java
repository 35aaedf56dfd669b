package org.robotrun;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The import rules of DESIGN.md ("Packages and who may import whom"). Every rule fails when the
 * package it names has no classes (ArchUnit's default), so a renamed package cannot pass by being
 * empty.
 */
class ArchitectureTest {
  private static final List<String> CORE =
      List.of("math", "robot", "collision", "world", "program", "motion", "sim", "control", "pendant", "io");
  private static final List<String> ALL =
      List.of("math", "robot", "collision", "world", "program", "motion", "sim", "control", "pendant", "io", "grade",
          "render", "ui", "app");
  /** Packages that run headless: the core and grading. */
  private static final List<String> HEADLESS =
      List.of("math", "robot", "collision", "world", "program", "motion", "sim", "control", "pendant", "io", "grade");

  /** Which of our packages each package may use (besides itself). */
  private static final Map<String, List<String>> ALLOWED = Map.ofEntries(
      Map.entry("math", List.of()),
      Map.entry("robot", List.of("math")),
      Map.entry("collision", List.of("math")),
      Map.entry("world", List.of("math", "collision")),
      Map.entry("program", List.of("math")),
      Map.entry("motion", List.of("math", "robot")),
      // sim implements the control port; control is the small core both sides share
      Map.entry("sim", List.of("math", "robot", "collision", "world", "program", "motion", "control")),
      Map.entry("control", List.of("math", "program")),
      // the pendant reaches a controller only through the control port, never sim
      Map.entry("pendant", List.of("math", "program", "control")),
      Map.entry("io", CORE),
      Map.entry("grade", CORE),
      Map.entry("render", CORE),
      Map.entry("ui", ALL),
      Map.entry("app", ALL));

  private static JavaClasses classes;

  @BeforeAll
  static void importMainClasses() {
    classes = new ClassFileImporter()
        .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
        .importPackages("org.robotrun");
  }

  /** DESIGN.md's one exception: io may read mesh files through LWJGL's Assimp binding, in this class only. */
  private static final String ASSIMP_READER = "org.robotrun.io.AssimpMeshes";

  @Test
  void corePackagesDoNotTouchOpenGlUiOrApp() {
    for (String p : HEADLESS) {
      noClasses().that().resideInAPackage("org.robotrun." + p + "..")
          .and().doNotHaveFullyQualifiedName(ASSIMP_READER)
          .should().dependOnClassesThat().resideInAnyPackage(
              "org.lwjgl..", "imgui..", "org.robotrun.render..", "org.robotrun.ui..", "org.robotrun.app..")
          .check(classes);
    }
  }

  @Test
  void theAssimpReaderUsesOnlyAssimpAndLwjglsMemoryTypes() {
    noClasses().that().haveFullyQualifiedName(ASSIMP_READER)
        .should().dependOnClassesThat().resideInAnyPackage(
            "org.lwjgl.opengl..", "org.lwjgl.glfw..", "org.lwjgl.stb..", "org.lwjgl.nfd..", "imgui..",
            "org.robotrun.render..", "org.robotrun.ui..", "org.robotrun.app..")
        .check(classes);
  }

  @Test
  void eachPackageImportsOnlyWhatTheDesignAllows() {
    for (Map.Entry<String, List<String>> e : ALLOWED.entrySet()) {
      String[] forbidden = ALL.stream()
          .filter(p -> !p.equals(e.getKey()) && !e.getValue().contains(p))
          .map(p -> "org.robotrun." + p + "..")
          .toArray(String[]::new);
      if (forbidden.length == 0) {
        continue;
      }
      noClasses().that().resideInAPackage("org.robotrun." + e.getKey() + "..")
          .should().dependOnClassesThat().resideInAnyPackage(forbidden)
          .check(classes);
    }
  }

  @Test
  void everyPackageOfTheProjectIsInTheTable() {
    java.util.Set<String> packages = new java.util.TreeSet<>();
    classes.forEach(c -> {
      String rest = c.getPackageName().substring(Math.min(c.getPackageName().length(), "org.robotrun.".length()));
      if (c.getPackageName().startsWith("org.robotrun.")) {
        packages.add(rest.contains(".") ? rest.substring(0, rest.indexOf('.')) : rest);
      }
    });
    org.assertj.core.api.Assertions.assertThat(packages).containsExactlyInAnyOrderElementsOf(ALL);
    org.assertj.core.api.Assertions.assertThat(ALLOWED.keySet()).containsExactlyInAnyOrderElementsOf(ALL);
  }

  @Test
  void thePendantReachesAControllerOnlyThroughTheControlPort() {
    noClasses().that().resideInAPackage("org.robotrun.pendant..")
        .should().dependOnClassesThat().resideInAnyPackage("org.robotrun.sim..", "org.robotrun.motion..",
            "org.robotrun.robot..")
        .check(classes);
  }

  @Test
  void onlyTheControllerImplementsTheControlPortSoNothingInAppStandsBetween() {
    // a jog key goes pendant -> control.RobotControl -> sim (issue 23): no adapter in app or elsewhere
    com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes()
        .that().implement(org.robotrun.control.RobotControl.class)
        .should().resideInAPackage("org.robotrun.sim..")
        .check(classes);
  }

  @Test
  void programReachesTheRobotOnlyThroughItsOwnPort() {
    noClasses().that().resideInAPackage("org.robotrun.program..")
        .should().dependOnClassesThat().resideInAnyPackage("org.robotrun.motion..", "org.robotrun.robot..")
        .check(classes);
  }
}
