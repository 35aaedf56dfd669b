package org.robotrun.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.jar.JarFile;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import org.robotrun.io.AtomicFiles;

/**
 * Puts this platform's LWJGL and Dear ImGui natives in a folder of their own before the first
 * native call, and points {@code org.lwjgl.librarypath} and {@code imgui.library.path} at it.
 *
 * <p>Why: left to themselves, LWJGL and imgui-java extract their libraries at every start to
 * fixed paths under the temporary folder, overwriting what is there. A second RobotRun starting
 * at the same moment rewrites a {@code .so} the first has just mapped, and the first dies with
 * SIGBUS (seen: 2 of 16 window starts during issue 19's measurements). Here the folder is named
 * by the libraries' content (a SHA-256 over each library's name, size and CRC-32, as the jar's
 * directory gives them, so nothing is unpacked to compute it), filled under a unique temporary
 * name and renamed into place in one step: a folder that exists is complete and never changes,
 * and two processes that race both end up loading the same, whole files.
 *
 * <p>The folder is in the user's cache ({@code $XDG_CACHE_HOME/robotrun}, {@code ~/.cache/robotrun},
 * {@code ~/Library/Caches/RobotRun}, {@code %LOCALAPPDATA%\RobotRun\cache}; {@code ROBOTRUN_CACHE_DIR}
 * overrides), not the temporary folder, which lab machines often mount {@code noexec}. Nothing is
 * done when the properties are already set (the installed app ships its natives unpacked beside
 * the jar) or when this platform has no natives in the class path; when the cache cannot be
 * written, the libraries' own extraction is left to run as before.
 */
final class NativeLibraries {
  private NativeLibraries() {}

  static final String LWJGL_PATH = "org.lwjgl.librarypath";
  static final String IMGUI_PATH = "imgui.library.path";
  /**
   * LWJGL loads a library it finds in the class path through its SharedLibraryLoader, which
   * "extracts" it into this folder: finding each file there already, whole and with the right
   * CRC, it writes nothing.
   */
  static final String LWJGL_EXTRACT_PATH = "org.lwjgl.system.SharedLibraryExtractPath";

  private static Optional<Path> prepared;

  /** Prepares the natives once per process; the folder used, if any. Never throws. */
  static synchronized Optional<Path> prepare() {
    if (prepared == null) {
      prepared = Optional.empty();
      if (System.getProperty(LWJGL_PATH) == null && System.getProperty(IMGUI_PATH) == null) {
        try {
          Optional<Path> root = cacheRoot(System.getenv(), System.getProperty("os.name", ""),
              System.getProperty("user.home", ""));
          if (root.isPresent()) {
            prepared = install(root.get().resolve("natives"), Natives.currentPlatform(),
                NativeLibraries.class.getClassLoader());
          }
        } catch (IOException | RuntimeException e) {
          // The libraries extract themselves as they always did: slower to share, not fatal.
        }
        prepared.ifPresent(dir -> {
          System.setProperty(LWJGL_PATH, dir.toString());
          System.setProperty(LWJGL_EXTRACT_PATH, dir.toString());
          System.setProperty(IMGUI_PATH, dir.toString());
        });
      }
    }
    return prepared;
  }

  /** The user's cache folder for RobotRun on this OS, if one can be named. */
  static Optional<Path> cacheRoot(Map<String, String> env, String osName, String home) {
    String own = env.get("ROBOTRUN_CACHE_DIR");
    if (own != null && !own.isBlank()) {
      return Optional.of(Path.of(own));
    }
    String os = osName.toLowerCase(Locale.ROOT);
    if (os.startsWith("windows")) {
      String local = env.get("LOCALAPPDATA");
      return local == null || local.isBlank() ? Optional.empty() : Optional.of(Path.of(local, "RobotRun", "cache"));
    }
    if (home.isEmpty()) {
      return Optional.empty();
    }
    if (os.startsWith("mac")) {
      return Optional.of(Path.of(home, "Library", "Caches", "RobotRun"));
    }
    String xdg = env.get("XDG_CACHE_HOME");
    return Optional.of(xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute()
        ? Path.of(xdg, "robotrun") : Path.of(home, ".cache", "robotrun"));
  }

  /** One native library found in the class path. */
  record Library(String fileName, long size, long crc, Source source) {}

  /** Where a library's bytes come from. */
  interface Source {
    InputStream open() throws IOException;
  }

  /**
   * Makes sure {@code nativesRoot/<platform>-<content hash>} holds this platform's libraries and
   * returns it; empty when the class path has none for the platform.
   */
  static Optional<Path> install(Path nativesRoot, String platform, ClassLoader loader) throws IOException {
    List<Library> libs = find(platform, loader);
    if (libs.isEmpty()) {
      return Optional.empty();
    }
    Path dir = nativesRoot.resolve(platform + "-" + contentHash(libs));
    if (complete(dir, libs)) {
      return Optional.of(dir);
    }
    Files.createDirectories(nativesRoot);
    Path temp = Files.createTempDirectory(nativesRoot, ".partial-");
    try {
      for (Library l : libs) {
        try (InputStream in = l.source().open()) {
          AtomicFiles.write(temp.resolve(l.fileName()), in.readAllBytes());
        }
      }
      try {
        Files.move(temp, dir, StandardCopyOption.ATOMIC_MOVE);
      } catch (FileAlreadyExistsException | DirectoryNotEmptyException e) {
        // Another process got there first with the same content: use its folder.
      } catch (AtomicMoveNotSupportedException e) {
        return Optional.empty();
      } catch (IOException e) {
        // Windows says "access denied" when the folder appeared meanwhile: checked below.
      }
    } finally {
      deleteTree(temp);
    }
    // A folder left incomplete by hand (files deleted) is not ours to repair while others use it.
    return complete(dir, libs) ? Optional.of(dir) : Optional.empty();
  }

  /** The folder holds every library at its size (a rename made it whole; this guards hand edits). */
  private static boolean complete(Path dir, List<Library> libs) {
    for (Library l : libs) {
      Path f = dir.resolve(l.fileName());
      try {
        if (!Files.isRegularFile(f) || Files.size(f) != l.size()) {
          return false;
        }
      } catch (IOException e) {
        return false;
      }
    }
    return true;
  }

  static String contentHash(List<Library> libs) {
    try {
      MessageDigest md = MessageDigest.getInstance("SHA-256");
      for (Library l : libs) {
        md.update((l.fileName() + "\u0000" + l.size() + "\u0000" + Long.toHexString(l.crc()) + "\n")
            .getBytes(StandardCharsets.UTF_8));
      }
      return HexFormat.of().formatHex(md.digest(), 0, 12);
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException(e);
    }
  }

  /**
   * This platform's libraries: every file in LWJGL's {@code <os>/<arch>/} folders (one per
   * LWJGL jar, or all in the one shaded jar) and imgui-java's library, sorted by file name.
   */
  static List<Library> find(String platform, ClassLoader loader) throws IOException {
    int dash = platform.indexOf('-');
    String os = platform.substring(0, dash);
    String arch = platform.substring(dash + 1);
    String suffix = switch (os) {
      case "windows" -> ".dll";
      case "macos" -> ".dylib";
      default -> ".so";
    };
    Map<String, Library> out = new TreeMap<>();
    String prefix = os + "/" + arch + "/";
    for (URL root : Collections.list(loader.getResources(prefix + "org/lwjgl/"))) {
      collect(root, prefix, suffix, out);
    }
    if (arch.equals("x64")) {
      String imgui = switch (os) {
        case "windows" -> "imgui-java64.dll";
        case "macos" -> "libimgui-java64.dylib";
        default -> "libimgui-java64.so";
      };
      URL u = loader.getResource("io/imgui/java/native-bin/" + imgui);
      if (u != null) {
        collect(u, "io/imgui/java/native-bin/", suffix, out);
      }
    }
    return List.copyOf(out.values());
  }

  /** Adds the libraries under {@code url} (a jar folder or file, or a class-path folder). */
  private static void collect(URL url, String prefix, String suffix, Map<String, Library> out) throws IOException {
    switch (url.getProtocol()) {
      case "jar" -> {
        JarURLConnection c = (JarURLConnection) url.openConnection();
        c.setUseCaches(false);
        String at = c.getEntryName();
        Path jarPath;
        try {
          jarPath = Path.of(c.getJarFileURL().toURI());
        } catch (URISyntaxException | IllegalArgumentException e) {
          return;
        }
        try (JarFile jar = new JarFile(jarPath.toFile())) {
          List<ZipEntry> entries = new ArrayList<>();
          jar.stream().filter(e -> !e.isDirectory() && e.getName().startsWith(at) && e.getName().endsWith(suffix))
              .forEach(entries::add);
          for (ZipEntry e : entries) {
            String name = e.getName();
            String file = name.substring(name.lastIndexOf('/') + 1);
            out.put(file, new Library(file, e.getSize(), e.getCrc(), () -> {
              JarFile j = new JarFile(jarPath.toFile());
              InputStream in = j.getInputStream(j.getEntry(name));
              return new java.io.FilterInputStream(in) {
                @Override
                public void close() throws IOException {
                  super.close();
                  j.close();
                }
              };
            }));
          }
        }
      }
      case "file" -> {
        Path p;
        try {
          p = Path.of(url.toURI());
        } catch (URISyntaxException | IllegalArgumentException e) {
          return;
        }
        List<Path> files;
        try (Stream<Path> s = Files.isDirectory(p) ? Files.walk(p) : Stream.of(p)) {
          files = s.filter(Files::isRegularFile).filter(f -> f.getFileName().toString().endsWith(suffix)).toList();
        }
        for (Path f : files) {
          byte[] bytes = Files.readAllBytes(f);
          java.util.zip.CRC32 crc = new java.util.zip.CRC32();
          crc.update(bytes);
          String file = f.getFileName().toString();
          out.put(file, new Library(file, bytes.length, crc.getValue(), () -> new java.io.ByteArrayInputStream(bytes)));
        }
      }
      default -> {
        // another kind of class path: left to the libraries' own extraction
      }
    }
  }

  private static void deleteTree(Path dir) {
    if (!Files.exists(dir)) {
      return;
    }
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.sorted(Collections.reverseOrder()).toList()) {
        Files.deleteIfExists(p);
      }
    } catch (IOException | UncheckedIOException e) {
      // a leftover ".partial-" folder is harmless
    }
  }
}
