package org.robotrun.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Where RobotRun keeps a user's things, in each platform's usual place: the default workspace
 * (Linux {@code $XDG_DATA_HOME/robotrun/workspace}, else {@code ~/.local/share/robotrun/workspace};
 * Windows {@code %APPDATA%\RobotRun\workspace}; macOS
 * {@code ~/Library/Application Support/RobotRun/workspace}) and a small settings folder
 * (Linux {@code $XDG_CONFIG_HOME/robotrun}, else {@code ~/.config/robotrun}; the same RobotRun
 * folder on Windows and macOS) with the last and recent workspaces.
 *
 * <p>{@code ROBOTRUN_DATA_DIR} and {@code ROBOTRUN_CONFIG_DIR} (environment) replace the two
 * base folders, so tests and portable installs never touch the real home.
 */
public final class UserDirs {
  /** How many recent workspaces are remembered. */
  public static final int RECENT = 8;
  private static final String RECENT_FILE = "recent-workspaces.txt";

  private final Path dataDir;
  private final Path configDir;

  public UserDirs(Path dataDir, Path configDir) {
    this.dataDir = dataDir;
    this.configDir = configDir;
  }

  /** The folders for this machine and user, from the environment and system properties. */
  public static UserDirs fromSystem() {
    return of(System.getenv(), System.getProperty("os.name", ""), System.getProperty("user.home", "."));
  }

  /** The folders for a given environment, operating system name and home folder. */
  public static UserDirs of(Map<String, String> env, String osName, String home) {
    String os = osName.toLowerCase(Locale.ROOT);
    Path h = Path.of(home);
    Path data;
    Path config;
    if (os.startsWith("windows")) {
      Path appData = env.containsKey("APPDATA") ? Path.of(env.get("APPDATA")) : h.resolve("AppData").resolve("Roaming");
      data = appData.resolve("RobotRun");
      config = data;
    } else if (os.startsWith("mac")) {
      data = h.resolve("Library").resolve("Application Support").resolve("RobotRun");
      config = data;
    } else {
      data = absoluteOr(env.get("XDG_DATA_HOME"), h.resolve(".local").resolve("share")).resolve("robotrun");
      config = absoluteOr(env.get("XDG_CONFIG_HOME"), h.resolve(".config")).resolve("robotrun");
    }
    if (env.get("ROBOTRUN_DATA_DIR") != null && !env.get("ROBOTRUN_DATA_DIR").isBlank()) {
      data = Path.of(env.get("ROBOTRUN_DATA_DIR"));
    }
    if (env.get("ROBOTRUN_CONFIG_DIR") != null && !env.get("ROBOTRUN_CONFIG_DIR").isBlank()) {
      config = Path.of(env.get("ROBOTRUN_CONFIG_DIR"));
    }
    return new UserDirs(data.toAbsolutePath(), config.toAbsolutePath());
  }

  /** XDG says a relative value is to be ignored. */
  private static Path absoluteOr(String value, Path fallback) {
    try {
      if (value != null && !value.isBlank() && Path.of(value).isAbsolute()) {
        return Path.of(value);
      }
    } catch (InvalidPathException e) {
      // fall back
    }
    return fallback;
  }

  /** The workspace {@code robotrun} opens when none was opened before. */
  public Path defaultWorkspace() {
    return dataDir.resolve("workspace");
  }

  /**
   * A new folder for a workspace copied from a scenario named {@code stem}:
   * {@code <data>/workspaces/<stem>}, or {@code <stem>-2}, {@code -3} ... when taken.
   */
  public Path newWorkspaceFor(String stem) {
    String clean = stem.replaceAll("[^A-Za-z0-9_.-]", "_");
    Path base = dataDir.resolve("workspaces");
    Path p = base.resolve(clean);
    for (int n = 2; Files.exists(p); n++) {
      p = base.resolve(clean + "-" + n);
    }
    return p;
  }

  /** The settings folder (last and recent workspaces). */
  public Path configDir() {
    return configDir;
  }

  /** Workspaces opened before, newest first; folders that no longer exist are left out. */
  public List<Path> recentWorkspaces() {
    Path f = configDir.resolve(RECENT_FILE);
    List<Path> out = new ArrayList<>();
    try {
      if (!Files.exists(f)) {
        return out;
      }
      // A regular file only (a FIFO would block), 64 KiB at most, damaged bytes replaced.
      byte[] bytes = BoundedFiles.read(f, 64 * 1024, "recent-workspace lists");
      for (String line : new String(bytes, StandardCharsets.UTF_8).split("\n")) {
        try {
          Path p = Path.of(line.strip());
          if (!line.isBlank() && p.isAbsolute() && Files.isDirectory(p) && !out.contains(p) && out.size() < RECENT) {
            out.add(p);
          }
        } catch (InvalidPathException e) {
          // a damaged line is skipped
        }
      }
    } catch (IOException e) {
      // no list: nothing recent
    }
    return out;
  }

  /** The workspace opened last, if it still exists. */
  public Optional<Path> lastWorkspace() {
    List<Path> r = recentWorkspaces();
    return r.isEmpty() ? Optional.empty() : Optional.of(r.get(0));
  }

  /** Puts {@code workspace} first in the recent list (written atomically). */
  public void remember(Path workspace) throws IOException {
    Path abs = workspace.toAbsolutePath().normalize();
    List<Path> list = new ArrayList<>(recentWorkspaces());
    list.remove(abs);
    list.add(0, abs);
    StringBuilder sb = new StringBuilder();
    list.stream().limit(RECENT).forEach(p -> sb.append(p).append('\n'));
    Files.createDirectories(configDir);
    AtomicFiles.write(configDir.resolve(RECENT_FILE), sb.toString().getBytes(StandardCharsets.UTF_8));
  }
}
