package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The JDK lookup of ./mvnw and ./robotrun (.mvn/find-jdk.sh, issue 30): with JAVA_HOME unset and
 * a Java 17 first on the PATH, the build still finds and uses an installed JDK 21+; with none
 * installed it says in one line how to get one. The fake JDKs are shell scripts with a
 * {@code release} file, so the test does not depend on what this machine has installed; the last
 * test runs the real {@code ./mvnw -B -q -o validate}, whose enforcer rule fails on anything
 * older than 21.
 */
class JdkLookupScriptTest {
  @TempDir Path tmp;
  Path java17;
  Path roots;

  @BeforeEach
  void posixShell() {
    assumeFalse(System.getProperty("os.name").startsWith("Windows"), "the POSIX scripts; mvnw.cmd has find-jdk.cmd");
  }

  /** A fake Java home: bin/java (and bin/javac) answering -version, and a release file. */
  Path fakeJdk(Path home, String version, boolean javac) throws IOException {
    Files.createDirectories(home.resolve("bin"));
    Files.writeString(home.resolve("release"), "IMPLEMENTOR=\"test\"\nJAVA_VERSION=\"" + version + "\"\n");
    List<String> tools = javac ? List.of("java", "javac") : List.of("java");
    for (String tool : tools) {
      Path t = home.resolve("bin").resolve(tool);
      Files.writeString(t, "#!/bin/sh\necho 'openjdk version \"" + version + "\" 2024-01-01' >&2\n");
      Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("rwxr-xr-x"));
    }
    return home;
  }

  record Result(int exit, String out, String err) {}

  Result sh(String script, Map<String, String> env) throws Exception {
    ProcessBuilder pb = new ProcessBuilder("sh", "-c", script).directory(Path.of("").toAbsolutePath().toFile());
    pb.environment().remove("JAVA_HOME");
    pb.environment().remove("SDKMAN_DIR");
    pb.environment().putAll(env);
    Path out = tmp.resolve("out.txt");
    Path err = tmp.resolve("err.txt");
    pb.redirectOutput(out.toFile()).redirectError(err.toFile());
    Process p = pb.start();
    assertThat(p.waitFor(120, TimeUnit.SECONDS)).as("finished").isTrue();
    return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8).strip(),
        Files.readString(err, StandardCharsets.UTF_8).strip());
  }

  @BeforeEach
  void fakes() throws IOException {
    java17 = fakeJdk(tmp.resolve("jdk17"), "17.0.15", true);
    roots = tmp.resolve("jvm");
    Files.createDirectories(roots);
  }

  Map<String, String> env(String path) {
    return Map.of("PATH", path + ":/usr/bin:/bin", "HOME", tmp.resolve("home").toString(),
        "ROBOTRUN_JDK_ROOTS", roots.toString());
  }

  @Test
  void aJava17OnThePathIsPassedOverForTheNewestInstalledJdk21() throws Exception {
    fakeJdk(roots.resolve("jdk-21"), "21.0.4", true);
    fakeJdk(roots.resolve("jdk-25"), "25.0.1", true);
    fakeJdk(roots.resolve("jre-26"), "26", false); // a runtime without javac cannot build
    fakeJdk(roots.resolve("jdk-1.8"), "1.8.0_392", true);
    Result r = sh(". ./.mvn/find-jdk.sh; rr_find_java_home javac; rr_find_java_home java",
        env(java17.resolve("bin").toString()));
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out().lines().toList()).containsExactly(roots.resolve("jdk-25").toString(), roots.resolve("jre-26").toString());
  }

  @Test
  void aJdk21OnThePathOrInJavaHomeIsUsedFirst() throws Exception {
    fakeJdk(roots.resolve("jdk-25"), "25.0.1", true);
    Path onPath = fakeJdk(tmp.resolve("jdk21"), "21.0.4", true);
    Result r = sh(". ./.mvn/find-jdk.sh; rr_find_java_home javac", env(onPath.resolve("bin").toString()));
    assertThat(r.out()).isEqualTo(onPath.toString());
    Map<String, String> withHome = new java.util.HashMap<>(env(java17.resolve("bin").toString()));
    Path home = fakeJdk(tmp.resolve("jdk22"), "22", true);
    withHome.put("JAVA_HOME", home.toString());
    assertThat(sh(". ./.mvn/find-jdk.sh; rr_find_java_home javac", withHome).out()).isEqualTo(home.toString());
    // JAVA_HOME at a 17 is passed over too.
    withHome.put("JAVA_HOME", java17.toString());
    assertThat(sh(". ./.mvn/find-jdk.sh; rr_find_java_home javac", withHome).out()).isEqualTo(roots.resolve("jdk-25").toString());
  }

  @Test
  void sdkmanCandidatesAreFound() throws Exception {
    Path sdk = tmp.resolve("sdkman");
    fakeJdk(sdk.resolve("candidates/java/21.0.4-tem"), "21.0.4", true);
    Map<String, String> e = new java.util.HashMap<>(env(java17.resolve("bin").toString()));
    e.put("SDKMAN_DIR", sdk.toString());
    assertThat(sh(". ./.mvn/find-jdk.sh; rr_find_java_home javac", e).out())
        .isEqualTo(sdk.resolve("candidates/java/21.0.4-tem").toString());
  }

  @Test
  void withNoJdk21AnywhereMvnwSaysInOneLineHowToGetOne() throws Exception {
    Result r = sh("./mvnw -B -q -o validate", env(java17.resolve("bin").toString()));
    assertThat(r.exit()).isEqualTo(1);
    assertThat(r.err().lines().toList()).singleElement().asString()
        .startsWith("RobotRun needs a JDK 21 or newer and found none").contains("install one: ");
  }

  @Test
  void mvnwValidatesWithJavaHomeUnsetAndJava17FirstOnThePath() throws Exception {
    // The real thing on this machine: a Java 17 first on the PATH (the machine's own, or a fake that would
    // fail the enforcer), JAVA_HOME unset, and the system's JDK folders searched as usual.
    Path real17 = Path.of("/usr/lib/jvm/java-17-openjdk-amd64/bin");
    String path = Files.isExecutable(real17.resolve("java")) ? real17.toString() : java17.resolve("bin").toString();
    Result r = sh("./mvnw -B -q -o validate", Map.of("PATH", path + ":/usr/bin:/bin"));
    assertThat(r.exit()).as("stdout: %s%nstderr: %s", r.out(), r.err()).isZero();
  }
}
