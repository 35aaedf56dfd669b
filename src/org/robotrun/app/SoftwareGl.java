package org.robotrun.app;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The fall-back to Mesa's software renderer when the graphics driver offers no OpenGL 3.3 core
 * context (old Intel GPUs, virtual machines, remote desktops). Mesa picks its renderer when the
 * process loads libGL, from the environment, so the fall-back starts RobotRun again, same command
 * line, with {@code LIBGL_ALWAYS_SOFTWARE=1} and {@code GALLIUM_DRIVER=llvmpipe} (Mesa's
 * environment variables, docs.mesa3d.org/envvars.html) and says so. Only on Linux and the BSDs,
 * where Mesa is the system's libGL; only once (the marker variable stops a loop).
 */
final class SoftwareGl {
  /** Set in the second process; the window title and messages say software rendering. */
  static final String MARKER = "ROBOTRUN_SOFTWARE_GL";

  private SoftwareGl() {}

  /** Whether a failed OpenGL 3.3 context may be retried with Mesa's software renderer. */
  static boolean mayRetry(String osName, Map<String, String> env) {
    String os = osName.toLowerCase(Locale.ROOT);
    boolean mesaIsLibGl = os.startsWith("linux") || os.endsWith("bsd");
    return mesaIsLibGl && !env.containsKey(MARKER) && !"1".equals(env.get("LIBGL_ALWAYS_SOFTWARE"));
  }

  /** Whether this process is the software-rendering retry. */
  static boolean active(Map<String, String> env) {
    return env.containsKey(MARKER);
  }

  /** The variables added for the retry. */
  static Map<String, String> environment() {
    return Map.of("LIBGL_ALWAYS_SOFTWARE", "1", "GALLIUM_DRIVER", "llvmpipe", MARKER, "1");
  }

  /** This process's command line (the launcher or java with its options), if the OS tells it. */
  static Optional<List<String>> commandLine(ProcessHandle.Info info) {
    Optional<String> cmd = info.command();
    Optional<String[]> args = info.arguments();
    if (cmd.isEmpty() || args.isEmpty()) {
      return Optional.empty();
    }
    List<String> out = new ArrayList<>();
    out.add(cmd.get());
    out.addAll(List.of(args.get()));
    return Optional.of(out);
  }

  /**
   * Starts this program again with the software renderer, its input and output the terminal's,
   * and returns its exit code; empty when the command line is unknown or the start fails.
   */
  static Optional<Integer> relaunch() {
    Optional<List<String>> cmd = commandLine(ProcessHandle.current().info());
    if (cmd.isEmpty()) {
      return Optional.empty();
    }
    ProcessBuilder pb = new ProcessBuilder(cmd.get()).inheritIO();
    pb.environment().putAll(environment());
    try {
      return Optional.of(pb.start().waitFor());
    } catch (IOException e) {
      return Optional.empty();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      return Optional.of(Main.EXIT_FAILED);
    }
  }
}
