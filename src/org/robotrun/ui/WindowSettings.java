package org.robotrun.ui;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.Properties;
import org.robotrun.io.AtomicFiles;

/**
 * Where the window keeps its layout between runs, one per workspace ({@link #forWorkspace}) and the user's last one, {@code layout.properties},
 * in the user's settings folder ({@link org.robotrun.io.UserDirs#configDir}: {@code ROBOTRUN_CONFIG_DIR},
 * else {@code $XDG_CONFIG_HOME/robotrun} or {@code ~/.config/robotrun} on Linux, {@code %APPDATA%\RobotRun}
 * on Windows, {@code ~/Library/Application Support/RobotRun} on macOS), never the current directory.
 * Written through {@link AtomicFiles}.
 */
public final class WindowSettings {
  private static final String USER_FILE = "layout.properties";
  private final Optional<Path> dir;
  private final String fileName;

  public WindowSettings(Optional<Path> dir) {
    this(dir, USER_FILE);
  }

  private WindowSettings(Optional<Path> dir, String fileName) {
    this.dir = dir;
    this.fileName = fileName;
  }

  /**
   * The layout of one workspace: kept in the user's settings folder under a name derived from the
   * workspace's path (so a read-only workspace or a hand-in folder is never written to), starting
   * from the user's last layout when the workspace has none yet.
   */
  public static WindowSettings forWorkspace(Path workspaceFolder) {
    return forWorkspace(forUser(), workspaceFolder);
  }

  /** The layout of one workspace, kept beside {@code user}'s own layout file. */
  public static WindowSettings forWorkspace(WindowSettings user, Path workspaceFolder) {
    String key = workspaceFolder.toAbsolutePath().normalize().toString();
    try {
      byte[] h = java.security.MessageDigest.getInstance("SHA-256").digest(key.getBytes(StandardCharsets.UTF_8));
      return new WindowSettings(user.dir, "layout-" + java.util.HexFormat.of().formatHex(h, 0, 8) + ".properties");
    } catch (java.security.NoSuchAlgorithmException e) {
      throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
    }
  }

  /** The settings folder of this user on this system, as {@link org.robotrun.io.UserDirs} decides it (the one place). */
  public static WindowSettings forUser() {
    return new WindowSettings(Optional.of(org.robotrun.io.UserDirs.fromSystem().configDir()));
  }

  public Optional<Path> file() {
    return dir.map(d -> d.resolve(fileName));
  }

  /**
   * The saved layout, or (for a workspace seen for the first time) the user's last layout, or the
   * default one when there is none or it cannot be read.
   */
  public LayoutState load() {
    Optional<Path> f = file().filter(Files::isRegularFile)
        .or(() -> dir.map(d -> d.resolve(USER_FILE)).filter(Files::isRegularFile));
    if (f.isEmpty()) {
      return new LayoutState();
    }
    try {
      Properties p = new Properties();
      p.load(new StringReader(org.robotrun.io.BoundedFiles.readUtf8(f.get(), 1 << 20, "window settings")));
      return LayoutState.fromProperties(p);
    } catch (IOException | IllegalArgumentException | org.robotrun.io.FileFormatException e) {
      return new LayoutState();
    }
  }

  /** Saves the layout; returns a one-line problem, or "" when it was saved (or there is nowhere to). */
  public String save(LayoutState state) {
    Optional<Path> f = file();
    if (f.isEmpty()) {
      return "";
    }
    try {
      Files.createDirectories(f.get().getParent());
      StringWriter w = new StringWriter();
      state.toProperties().store(w, "RobotRun window layout");
      AtomicFiles.write(f.get(), w.toString().getBytes(StandardCharsets.UTF_8));
      if (!fileName.equals(USER_FILE)) {
        // the next new workspace starts from the layout the user left last
        AtomicFiles.write(dir.get().resolve(USER_FILE), w.toString().getBytes(StandardCharsets.UTF_8));
      }
      return "";
    } catch (IOException e) {
      return "could not save the window layout to " + f.get() + ": " + e.getMessage();
    }
  }
}
