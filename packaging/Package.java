import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.GradientPaint;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.spi.ToolProvider;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;
import javax.imageio.ImageIO;

/**
 * Builds RobotRun's installable packages for the platform it runs on, from the shaded jar, with the
 * JDK's own jdeps, jlink and jpackage (run as in-process tools, so the same file works on Linux,
 * Windows and macOS; {@code ./mvnw -Ppackage package} runs it with the JDK's source launcher).
 *
 * <p>Steps: the modules the jar needs (jdeps); a trimmed runtime with only those (jlink); a jar
 * with this platform's natives only, which are also unpacked next to it so nothing is extracted to
 * a temporary folder at start (lab machines often mount /tmp noexec); the app image (jpackage);
 * an AppCDS archive (or, with --aot true, a JDK 25 AOT cache) from a training run of that image; then the platform's packages from the image:
 * Linux .deb and .tar.gz, Windows .msi and .zip, macOS .dmg.
 *
 * <p>Arguments: {@code --jar FILE --version V --out DIR [--types LIST|auto] [--cds true|false] [--aot true|false] [--scenario FILE]}.
 * {@code --types} is a comma list of deb, tar.gz, msi, zip, dmg (default: all of this platform's).
 */
public final class Package {
  static final String NAME = "RobotRun";
  static final String MAIN = "org.robotrun.app.Main";
  static final String VENDOR = "RobotRun project";
  static final String DESCRIPTION = "Simulator of a 6-axis industrial robot arm for learning to operate and program robots";
  /** Fixed so a newer .msi replaces an older one instead of installing beside it. */
  static final String WIN_UPGRADE_UUID = "5f1c7a0e-2b7d-4c1e-9a43-7d0e5b6c2f19";

  final String os = os();
  final String arch = arch();
  Path jar;
  String version;
  Path out;
  Path work;
  Path scenario = Path.of("scenarios/pick-and-place.json");
  boolean cds = true;
  boolean aot;
  List<String> types;

  public static void main(String[] args) throws Exception {
    Package p = new Package();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--jar" -> p.jar = Path.of(args[++i]);
        case "--version" -> p.version = args[++i];
        case "--out" -> p.out = Path.of(args[++i]);
        case "--types" -> {
          String t = args[++i];
          p.types = t.equals("auto") ? null : Arrays.stream(t.split(",")).map(String::trim).filter(s -> !s.isEmpty()).toList();
        }
        case "--cds" -> p.cds = Boolean.parseBoolean(args[++i]);
        case "--aot" -> p.aot = Boolean.parseBoolean(args[++i]);
        case "--scenario" -> p.scenario = Path.of(args[++i]);
        default -> throw new IllegalArgumentException("unknown argument " + args[i]);
      }
    }
    if (p.jar == null || p.version == null || p.out == null) {
      throw new IllegalArgumentException("usage: Package --jar FILE --version V --out DIR [--types LIST|auto] [--cds true|false]");
    }
    if (p.types == null) {
      p.types = switch (p.os) {
        case "linux" -> List.of("deb", "tar.gz");
        case "windows" -> List.of("msi", "zip");
        case "macos" -> List.of("dmg");
        default -> throw new IllegalStateException("no packages for " + p.os);
      };
    }
    p.build();
  }

  void build() throws Exception {
    work = out.resolve("work");
    deleteTree(out);  // no package of an earlier build left beside the new ones
    Files.createDirectories(work);
    log("packaging RobotRun " + version + " for " + os + "-" + arch + ": " + types);

    List<String> modules = modules();
    Path runtime = jlink(modules);
    Path input = input();
    Path icon = icons();
    Path image = appImage(runtime, input, icon);
    if (cds) {
      trainCds(image);
    }
    for (String type : types) {
      switch (type) {
        case "tar.gz" -> tarGz(image, out.resolve(fileBase() + ".tar.gz"));
        case "zip" -> zip(image, out.resolve(fileBase() + ".zip"));
        case "deb", "msi", "dmg" -> installer(type, image, icon);
        default -> throw new IllegalArgumentException("unknown package type " + type);
      }
    }
    log("runtime image: " + mb(treeSize(runtime)) + ", app image: " + mb(treeSize(image)));
    try (Stream<Path> s = Files.list(out)) {
      for (Path f : s.filter(Files::isRegularFile).sorted().toList()) {
        log("package " + f.getFileName() + ": " + mb(Files.size(f)));
      }
    }
  }

  String fileBase() {
    return NAME + "-" + version + "-" + os + "-" + arch;
  }

  /** jpackage wants one to three numbers: the Maven version without its qualifier. */
  String appVersion() {
    String v = version.replaceFirst("-.*$", "");
    if (os.equals("macos") && v.startsWith("0.")) {
      // jpackage refuses a macOS bundle version whose first number is 0 (CFBundleVersion rule it
      // enforces); the file name and 'robotrun --version' keep the real version.
      return "1";
    }
    return v;
  }

  // ---- modules and runtime ----

  List<String> modules() {
    String feature = String.valueOf(Runtime.version().feature());
    String deps = tool("jdeps", "--ignore-missing-deps", "--multi-release", feature, "--print-module-deps", jar.toString()).trim();
    List<String> mods = new ArrayList<>(Arrays.asList(deps.split(",")));
    // Not seen by jdeps (no static reference): jdk.zipfs is not needed; the locale data for the
    // students' own languages is (number and date formats in file dialogs and messages).
    if (!mods.contains("jdk.localedata")) {
      mods.add("jdk.localedata");
    }
    log("modules (jdeps + locale data): " + String.join(",", mods));
    return mods;
  }

  /**
   * With --aot true (JDK 25 or newer): an AOT cache (JEP 483/514, AppCDS's successor that also
   * keeps classes linked and method profiles) instead of a dynamic AppCDS archive. Off by default:
   * with Temurin 25 every start of the packaged app printed "Failed to link AdapterHandlerEntry"
   * warnings from the cache's adapter code (the JVM recovers, but students would see them), for a
   * first-frame gain within this machine's noise. Dynamic AppCDS is mature since JDK 13.
   */
  boolean aotCache() {
    return aot && Runtime.version().feature() >= 25;
  }

  Path jlink(List<String> modules) throws IOException {
    Path runtime = work.resolve("runtime");
    List<String> args = new ArrayList<>(List.of(
        "--add-modules", String.join(",", modules),
        "--strip-debug", "--no-header-files", "--no-man-pages", "--compress=zip-6",
        "--include-locales=en,de,fr,es,it,pt,nl,pl,cs,sv,fi,da,nb,tr,ru,uk,zh,ja,ko",
        "--output", runtime.toString()));
    if (!aotCache()) {
      // The JDK's default class-data archive for the trimmed module set: the base a dynamic
      // AppCDS archive builds on. (JDK 25's AOT cache holds the JDK's classes itself.)
      args.add(0, "--generate-cds-archive");
    }
    tool("jlink", args.toArray(String[]::new));
    // Only used with heaps over 32 GB; never for this app.
    Files.deleteIfExists(runtime.resolve(os.equals("windows") ? "bin/server/classes_nocoops.jsa" : "lib/server/classes_nocoops.jsa"));
    return runtime;
  }

  // ---- the jar and natives for this platform ----

  /** LWJGL's folder for this platform's natives inside its jars. */
  String lwjglDir() {
    return os + "/" + arch + "/";
  }

  String imguiLib() {
    return switch (os) {
      case "linux" -> "libimgui-java64.so";
      case "windows" -> "imgui-java64.dll";
      default -> "libimgui-java64.dylib";
    };
  }

  boolean imguiHere() {
    return arch.equals("x64");  // imgui-java 1.86.11 publishes x86-64 natives only
  }

  Path input() throws IOException {
    Path input = work.resolve("input");
    Path natives = input.resolve("natives");
    Files.createDirectories(natives);
    int kept = 0;
    try (ZipInputStream in = new ZipInputStream(Files.newInputStream(jar));
        ZipOutputStream zout = new ZipOutputStream(Files.newOutputStream(input.resolve("robotrun.jar")))) {
      for (ZipEntry e; (e = in.getNextEntry()) != null; ) {
        String n = e.getName();
        if (isNative(n)) {
          String base = n.substring(n.lastIndexOf('/') + 1);
          boolean mine = n.startsWith(lwjglDir()) || (imguiHere() && n.equals("io/imgui/java/native-bin/" + imguiLib()));
          if (mine && !e.isDirectory()) {
            Files.copy(in, natives.resolve(base), StandardCopyOption.REPLACE_EXISTING);
            kept++;
          }
          continue;  // natives live beside the jar, not in it
        }
        ZipEntry copy = new ZipEntry(n);
        copy.setTime(e.getTime());
        zout.putNextEntry(copy);
        in.transferTo(zout);
        zout.closeEntry();
      }
    }
    // The example cells and programs, for students to open and for the smoke tests.
    copyTree(Path.of("scenarios"), input.resolve("scenarios"));
    if (kept == 0) {
      throw new IllegalStateException("the jar holds no natives for " + lwjglDir());
    }
    log("natives for " + os + "-" + arch + ": " + kept + " files" + (imguiHere() ? "" : " (no imgui-java natives for " + arch + ": the window will say so)"));
    return input;
  }

  static boolean isNative(String entry) {
    for (String platformDir : List.of("linux/", "windows/", "macos/", "freebsd/", "META-INF/linux/", "META-INF/windows/", "META-INF/macos/", "META-INF/freebsd/")) {
      if (entry.startsWith(platformDir)) {
        return true;
      }
    }
    return entry.startsWith("io/imgui/java/native-bin/");
  }

  // ---- icon: drawn here, no image files copied from anywhere ----

  static BufferedImage drawIcon(int size) {
    BufferedImage img = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
    Graphics2D g = img.createGraphics();
    g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
    g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
    float s = size / 256f;
    // Rounded tile, dark blue with a lighter top.
    g.setPaint(new GradientPaint(0, 0, new Color(0x2f, 0x5d, 0x8a), 0, size, new Color(0x14, 0x2a, 0x44)));
    g.fill(new RoundRectangle2D.Float(8 * s, 8 * s, 240 * s, 240 * s, 56 * s, 56 * s));
    // Floor line and base.
    g.setColor(new Color(0x9f, 0xb6, 0xcc));
    g.fill(new RoundRectangle2D.Float(40 * s, 206 * s, 176 * s, 10 * s, 10 * s, 10 * s));
    g.setColor(new Color(0x3a, 0x3a, 0x3a));
    g.fill(new RoundRectangle2D.Float(62 * s, 178 * s, 76 * s, 30 * s, 12 * s, 12 * s));
    // Two links in FANUC-style yellow, joined at round joints.
    Color yellow = new Color(0xf5, 0xc2, 0x1b);
    g.setColor(yellow);
    g.setStroke(new BasicStroke(34 * s, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    g.drawLine(Math.round(100 * s), Math.round(170 * s), Math.round(86 * s), Math.round(88 * s));
    g.setStroke(new BasicStroke(26 * s, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    g.drawLine(Math.round(86 * s), Math.round(88 * s), Math.round(176 * s), Math.round(66 * s));
    g.setColor(new Color(0x3a, 0x3a, 0x3a));
    for (float[] j : new float[][] {{100, 170, 15}, {86, 88, 13}, {176, 66, 10}}) {
      g.fill(new Ellipse2D.Float((j[0] - j[2]) * s, (j[1] - j[2]) * s, 2 * j[2] * s, 2 * j[2] * s));
    }
    // Gripper fingers under the wrist.
    g.setStroke(new BasicStroke(9 * s, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    g.setColor(new Color(0xd8, 0xdd, 0xe3));
    g.drawLine(Math.round(176 * s), Math.round(76 * s), Math.round(176 * s), Math.round(100 * s));
    g.drawLine(Math.round(164 * s), Math.round(100 * s), Math.round(188 * s), Math.round(100 * s));
    g.drawLine(Math.round(164 * s), Math.round(100 * s), Math.round(164 * s), Math.round(122 * s));
    g.drawLine(Math.round(188 * s), Math.round(100 * s), Math.round(188 * s), Math.round(122 * s));
    // The part it is about to pick.
    g.setColor(new Color(0x4c, 0xc9, 0x6e));
    g.fill(new RoundRectangle2D.Float(160 * s, 168 * s, 32 * s, 38 * s, 6 * s, 6 * s));
    g.dispose();
    return img;
  }

  static byte[] png(BufferedImage img) throws IOException {
    ByteArrayOutputStream b = new ByteArrayOutputStream();
    ImageIO.write(img, "png", b);
    return b.toByteArray();
  }

  /** The icon in the format this platform's jpackage wants: .png (Linux), .ico (Windows), .icns (macOS). */
  Path icons() throws IOException {
    Path dir = Files.createDirectories(work.resolve("icon"));
    Files.write(dir.resolve("robotrun.png"), png(drawIcon(256)));
    // ICO with PNG-compressed images (Windows Vista and later): header, directory, images.
    int[] icoSizes = {16, 32, 48, 256};
    List<byte[]> pngs = new ArrayList<>();
    for (int sz : icoSizes) {
      pngs.add(png(drawIcon(sz)));
    }
    ByteArrayOutputStream ico = new ByteArrayOutputStream();
    writeLe16(ico, 0);
    writeLe16(ico, 1);
    writeLe16(ico, icoSizes.length);
    int offset = 6 + 16 * icoSizes.length;
    for (int i = 0; i < icoSizes.length; i++) {
      int sz = icoSizes[i];
      ico.write(sz >= 256 ? 0 : sz);
      ico.write(sz >= 256 ? 0 : sz);
      ico.write(0);
      ico.write(0);
      writeLe16(ico, 1);
      writeLe16(ico, 32);
      writeLe32(ico, pngs.get(i).length);
      writeLe32(ico, offset);
      offset += pngs.get(i).length;
    }
    for (byte[] p : pngs) {
      ico.write(p);
    }
    Files.write(dir.resolve("robotrun.ico"), ico.toByteArray());
    // ICNS: 'icns', total length, then (type, length incl. 8-byte header, PNG data) per size.
    Map<String, Integer> icnsTypes = new LinkedHashMap<>();
    icnsTypes.put("ic07", 128);
    icnsTypes.put("ic08", 256);
    icnsTypes.put("ic09", 512);
    ByteArrayOutputStream body = new ByteArrayOutputStream();
    DataOutputStream bodyOut = new DataOutputStream(body);
    for (Map.Entry<String, Integer> t : icnsTypes.entrySet()) {
      byte[] p = png(drawIcon(t.getValue()));
      bodyOut.write(t.getKey().getBytes(StandardCharsets.US_ASCII));
      bodyOut.writeInt(p.length + 8);
      bodyOut.write(p);
    }
    ByteArrayOutputStream icns = new ByteArrayOutputStream();
    DataOutputStream icnsOut = new DataOutputStream(icns);
    icnsOut.write("icns".getBytes(StandardCharsets.US_ASCII));
    icnsOut.writeInt(body.size() + 8);
    body.writeTo(icnsOut);
    Files.write(dir.resolve("robotrun.icns"), icns.toByteArray());
    return dir.resolve(switch (os) {
      case "windows" -> "robotrun.ico";
      case "macos" -> "robotrun.icns";
      default -> "robotrun.png";
    });
  }

  static void writeLe16(OutputStream o, int v) throws IOException {
    o.write(v & 0xff);
    o.write((v >> 8) & 0xff);
  }

  static void writeLe32(OutputStream o, int v) throws IOException {
    writeLe16(o, v & 0xffff);
    writeLe16(o, (v >>> 16) & 0xffff);
  }

  // ---- app image ----

  /** JVM options of every launcher: what ./robotrun passes, plus natives from the app folder. */
  List<String> javaOptions() {
    List<String> o = new ArrayList<>(List.of(
        "--enable-native-access=ALL-UNNAMED",
        "--sun-misc-unsafe-memory-access=allow",
        "-Dorg.lwjgl.librarypath=$APPDIR/natives",
        "-Dimgui.library.path=$APPDIR/natives",
        // One user's desktop app with a small heap: the serial collector has the least to set
        // up and the smallest footprint (not separately measured here; the training run and the
        // app use the same collector, as CDS requires for its archived heap objects).
        "-XX:+UseSerialGC"));
    if (os.equals("macos")) {
      o.add("-XstartOnFirstThread");
    }
    return o;
  }

  Path appImage(Path runtime, Path input, Path icon) throws IOException {
    Path dest = work.resolve("image");
    List<String> a = new ArrayList<>(List.of(
        "--type", "app-image",
        "--name", NAME,
        "--app-version", appVersion(),
        "--vendor", VENDOR,
        "--copyright", "RobotRun contributors, MIT licence",
        "--description", DESCRIPTION,
        "--icon", icon.toString(),
        "--input", input.toString(),
        "--main-jar", "robotrun.jar",
        "--main-class", MAIN,
        "--runtime-image", runtime.toString(),
        "--dest", dest.toString()));
    for (String opt : javaOptions()) {
      a.add("--java-options");
      a.add(opt);
    }
    if (os.equals("windows")) {
      // The main launcher has no console window; robotrun-cli.exe is the same program for a
      // terminal (run, check, grade, render print there).
      Path props = work.resolve("robotrun-cli.properties");
      Files.writeString(props, "win-console=true\ndescription=RobotRun command line\n");
      a.addAll(List.of("--add-launcher", "robotrun-cli=" + props));
    }
    if (os.equals("macos")) {
      a.addAll(List.of("--mac-package-identifier", "org.robotrun.RobotRun", "--mac-package-name", NAME,
          // jpackage prefixes "public.app-category." (LSApplicationCategoryType).
          "--mac-app-category", "education"));
    }
    tool("jpackage", a.toArray(String[]::new));
    return dest.resolve(os.equals("macos") ? NAME + ".app" : NAME);
  }

  /** Where the app's jar, .cfg files and natives are inside the image. */
  Path appDir(Path image) {
    return switch (os) {
      case "windows" -> image.resolve("app");
      case "macos" -> image.resolve("Contents/app");
      default -> image.resolve("lib/app");
    };
  }

  Path runtimeJava(Path image) {
    return switch (os) {
      case "windows" -> image.resolve("runtime/bin/java.exe");
      case "macos" -> image.resolve("Contents/runtime/Contents/Home/bin/java");
      default -> image.resolve("lib/runtime/bin/java");
    };
  }

  Path launcher(Path image) {
    return switch (os) {
      case "windows" -> image.resolve(NAME + ".exe");
      case "macos" -> image.resolve("Contents/MacOS/" + NAME);
      default -> image.resolve("bin/" + NAME);
    };
  }

  /**
   * Trains an AppCDS archive with the image's own runtime and class path: the window for a few
   * frames when a display (or xvfb-run) is there, else a headless run of the example scenario.
   * The archive goes into the app folder and every launcher's .cfg names it; a stale or mismatched
   * archive is ignored by the JVM (-Xshare:auto), so it can slow a start but never break one.
   */
  void trainCds(Path image) throws Exception {
    Path app = appDir(image);
    Path archive = app.resolve(aotCache() ? "robotrun.aot" : "robotrun.jsa");
    List<String> java = new ArrayList<>();
    java.add(runtimeJava(image).toString());
    for (String opt : javaOptions()) {
      java.add(opt.replace("$APPDIR", app.toString()));
    }
    java.add(aotCache() ? "-XX:AOTCacheOutput=" + archive : "-XX:ArchiveClassesAtExit=" + archive);
    java.add("-Xlog:cds*=off");
    java.add("-Xlog:aot*=off");
    java.addAll(List.of("-cp", app.resolve("robotrun.jar").toString(), MAIN));

    List<String> gui = new ArrayList<>(java);
    gui.addAll(List.of("gui", "--scenario", scenario.toAbsolutePath().toString(), "--quit-after-frames", "5"));
    // The window opens a workspace in the user's data folder: give the training run its own.
    Path home = Files.createDirectories(work.resolve("training-home"));
    Map<String, String> env = Map.of("HOME", home.toString(), "XDG_DATA_HOME", home.resolve("data").toString(),
        "XDG_CONFIG_HOME", home.resolve("config").toString(), "APPDATA", home.resolve("AppData").toString(),
        "LOCALAPPDATA", home.resolve("LocalAppData").toString());
    boolean display = os.equals("linux") ? System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null : !"1".equals(System.getenv("ROBOTRUN_PACKAGE_HEADLESS_TRAINING"));
    int code = -1;
    if (display) {
      code = run(gui, 120, env);
    } else if (os.equals("linux") && onPath("xvfb-run")) {
      List<String> x = new ArrayList<>(List.of("xvfb-run", "-a", "-s", "-screen 0 1366x768x24"));
      x.addAll(gui);
      code = run(x, 120, env);
    }
    if (code != 0) {
      log("CDS training: no window here (exit " + code + "), training on a headless run of " + scenario);
      List<String> headless = new ArrayList<>(java);
      headless.addAll(List.of("run", "--scenario", scenario.toAbsolutePath().toString()));
      code = run(headless, 300, env);
    }
    if (code != 0 || !Files.exists(archive)) {
      log("CDS training failed (exit " + code + "): packaging without an AppCDS archive");
      Files.deleteIfExists(archive);
      return;
    }
    // Every launcher's .cfg gets the archive; the launcher expands $APPDIR.
    try (Stream<Path> s = Files.list(app)) {
      for (Path cfg : s.filter(f -> f.toString().endsWith(".cfg")).toList()) {
        String text = Files.readString(cfg);
        String use = aotCache() ? "-XX:AOTCache=$APPDIR/robotrun.aot" : "-XX:SharedArchiveFile=$APPDIR/robotrun.jsa";
        // Quiet: a cache that does not fit (say, an edited jar) is skipped, never an error.
        text = text.replace("[JavaOptions]\n", "[JavaOptions]\njava-options=" + use + "\njava-options=-Xlog:cds*=off\njava-options=-Xlog:aot*=off\n");
        Files.writeString(cfg, text);
      }
    }
    log((aotCache() ? "AOT cache: " : "AppCDS archive: ") + mb(Files.size(archive)));
  }

  // ---- packages ----

  void installer(String type, Path image, Path icon) throws IOException {
    List<String> a = new ArrayList<>(List.of(
        "--type", type,
        "--app-image", image.toString(),
        "--name", NAME,
        "--app-version", appVersion(),
        "--vendor", VENDOR,
        "--copyright", "RobotRun contributors, MIT licence",
        "--description", DESCRIPTION,
        "--license-file", Path.of("LICENSE").toAbsolutePath().toString(),
        "--dest", work.resolve("installer").toString()));
    // .LS programs and .rrcell cells (scenarios under RobotRun's own extension: claiming .json
    // would take every JSON file from the user's editor) open in RobotRun from the file manager,
    // which runs 'RobotRun FILE'. Hand-ins stay .zip (course sites and Gradescope unpack zips), so
    // they are not claimed. macOS passes opened files as Apple events, which the GLFW window does
    // not receive, so no association there (docs/install.md).
    if (!type.equals("dmg")) {
      String iconPath = icon.toString().replace("\\", "/");
      for (String[] assoc : List.of(
          new String[] {"ls", "text/x-robotrun-tp", "RobotRun TP program"},
          new String[] {"rrcell", "application/x-robotrun-cell", "RobotRun cell"})) {
        Path fa = work.resolve(assoc[0] + "-association.properties");
        Files.writeString(fa, "extension=" + assoc[0] + "\nmime-type=" + assoc[1] + "\ndescription=" + assoc[2]
            + "\nicon=" + iconPath + "\n");
        a.addAll(List.of("--file-associations", fa.toString()));
      }
    }
    switch (type) {
      case "deb" -> {
        Path res = Files.createDirectories(work.resolve("deb-resources"));
        debScripts(res);
        a.addAll(List.of("--icon", icon.toString(),
            "--linux-package-name", "robotrun",
            "--linux-deb-maintainer", "robotrun@users.noreply.github.com",
            "--linux-menu-group", "Education;Science;Engineering;",
            "--linux-app-category", "education",
            "--linux-shortcut",
            // LWJGL opens libGL at run time, so jpackage cannot see it; Mesa's DRI drivers give
            // the software renderer the window falls back to.
            "--linux-package-deps", "libgl1, libgl1-mesa-dri",
            "--resource-dir", res.toString()));
      }
      case "msi" -> a.addAll(List.of("--icon", icon.toString(),
          // Per-user install: no administrator rights needed (into %LOCALAPPDATA%\Programs).
          "--win-per-user-install", "--win-menu", "--win-menu-group", NAME, "--win-shortcut",
          "--win-shortcut-prompt", "--win-dir-chooser", "--win-upgrade-uuid", WIN_UPGRADE_UUID));
      // The bundle identifier and menu-bar name are already in the app image's Info.plist.
      case "dmg" -> a.addAll(List.of("--icon", icon.toString()));
      default -> throw new IllegalArgumentException(type);
    }
    tool("jpackage", a.toArray(String[]::new));
    try (Stream<Path> s = Files.list(work.resolve("installer"))) {
      for (Path f : s.filter(f -> f.getFileName().toString().endsWith("." + type)).toList()) {
        String name = type.equals("deb") ? f.getFileName().toString() : fileBase() + "." + type;
        Files.move(f, out.resolve(name), StandardCopyOption.REPLACE_EXISTING);
      }
    }
  }

  /**
   * jpackage's .deb scripts, with the command-line launcher added: /usr/bin/robotrun points at
   * the installed launcher, so 'robotrun run ...' works in any terminal. jpackage fills in the
   * %...% placeholders as it does in its own default scripts.
   */
  static void debScripts(Path res) throws IOException {
    // jpackage's template.desktop with the file argument: without %f a double-clicked .LS file
    // would start RobotRun without it (one file per start: 'RobotRun FILE.LS').
    Files.writeString(res.resolve(NAME + ".desktop"), """
        [Desktop Entry]
        Name=APPLICATION_NAME
        Comment=APPLICATION_DESCRIPTION
        Exec=APPLICATION_LAUNCHER %f
        Icon=APPLICATION_ICON
        Terminal=false
        Type=Application
        Categories=DEPLOY_BUNDLE_CATEGORY
        DESKTOP_MIMES
        """);
    // jpackage's own templates (template.postinst / template.prerm of JDK 25) plus one line each.
    Files.writeString(res.resolve("postinst"), """
        #!/bin/sh
        # postinst script for APPLICATION_PACKAGE
        set -e
        package_type=deb
        LAUNCHER_AS_SERVICE_SCRIPTS

        case "$1" in
            configure)
        DESKTOP_COMMANDS_INSTALL
        LAUNCHER_AS_SERVICE_COMMANDS_INSTALL
            ln -sf /opt/robotrun/bin/RobotRun /usr/bin/robotrun
            ;;

            abort-upgrade|abort-remove|abort-deconfigure)
            ;;

            *)
                echo "postinst called with unknown argument \\`$1'" >&2
                exit 1
            ;;
        esac

        exit 0
        """);
    Files.writeString(res.resolve("prerm"), """
        #!/bin/sh
        # prerm script for APPLICATION_PACKAGE
        set -e
        package_type=deb
        COMMON_SCRIPTS
        DESKTOP_SCRIPTS
        LAUNCHER_AS_SERVICE_SCRIPTS

        case "$1" in
            remove|upgrade|deconfigure)
        DESKTOP_COMMANDS_UNINSTALL
        LAUNCHER_AS_SERVICE_COMMANDS_UNINSTALL
            if [ "$(readlink /usr/bin/robotrun)" = /opt/robotrun/bin/RobotRun ]; then rm -f /usr/bin/robotrun; fi
            ;;

            failed-upgrade)
            ;;

            *)
                echo "prerm called with unknown argument \\`$1'" >&2
                exit 1
            ;;
        esac

        exit 0
        """);
  }

  void tarGz(Path image, Path dest) throws Exception {
    // The system tar keeps the launchers' executable bits and the archive's file times.
    int code = run(List.of("tar", "-C", image.getParent().toString(), "-czf", dest.toAbsolutePath().toString(), image.getFileName().toString()), 600);
    if (code != 0) {
      throw new IllegalStateException("tar failed with exit " + code);
    }
  }

  void zip(Path image, Path dest) throws IOException {
    Path root = image.getParent();
    try (ZipOutputStream z = new ZipOutputStream(Files.newOutputStream(dest))) {
      Files.walkFileTree(image, new SimpleFileVisitor<>() {
        @Override
        public FileVisitResult visitFile(Path f, BasicFileAttributes attrs) throws IOException {
          ZipEntry e = new ZipEntry(root.relativize(f).toString().replace('\\', '/'));
          e.setLastModifiedTime(attrs.lastModifiedTime());
          z.putNextEntry(e);
          try (InputStream in = Files.newInputStream(f)) {
            in.transferTo(z);
          }
          z.closeEntry();
          return FileVisitResult.CONTINUE;
        }
      });
    }
  }

  // ---- helpers ----

  static String tool(String name, String... args) {
    ToolProvider t = ToolProvider.findFirst(name).orElseThrow(() -> new IllegalStateException(
        name + " is not in this JDK: package with a full JDK 21 or newer (JAVA_HOME)"));
    StringWriter outText = new StringWriter();
    StringWriter errText = new StringWriter();
    int code = t.run(new PrintWriter(outText, true), new PrintWriter(errText, true), args);
    if (code != 0) {
      throw new IllegalStateException(name + " failed (exit " + code + "): " + errText + outText
          + "\n  arguments: " + String.join(" ", args));
    }
    return outText.toString();
  }

  static int run(List<String> cmd, int timeoutSec) throws Exception {
    return run(cmd, timeoutSec, Map.of());
  }

  static int run(List<String> cmd, int timeoutSec, Map<String, String> env) throws Exception {
    log("$ " + String.join(" ", cmd));
    ProcessBuilder pb = new ProcessBuilder(cmd).inheritIO();
    pb.environment().putAll(env);
    Process p = pb.start();
    if (!p.waitFor(timeoutSec, TimeUnit.SECONDS)) {
      p.destroyForcibly();
      return -2;
    }
    return p.exitValue();
  }

  static boolean onPath(String program) {
    String path = System.getenv("PATH");
    if (path == null) {
      return false;
    }
    for (String d : path.split(java.io.File.pathSeparator)) {
      if (Files.isExecutable(Path.of(d, program))) {
        return true;
      }
    }
    return false;
  }

  static String os() {
    String n = System.getProperty("os.name").toLowerCase(Locale.ROOT);
    return n.startsWith("windows") ? "windows" : n.startsWith("mac") ? "macos" : "linux";
  }

  static String arch() {
    String a = System.getProperty("os.arch").toLowerCase(Locale.ROOT);
    return a.equals("amd64") || a.equals("x86_64") ? "x64" : a.equals("aarch64") ? "arm64" : a;
  }

  static long treeSize(Path dir) throws IOException {
    try (Stream<Path> s = Files.walk(dir)) {
      return s.filter(Files::isRegularFile).mapToLong(f -> f.toFile().length()).sum();
    }
  }

  static String mb(long bytes) {
    return String.format(Locale.ROOT, "%.1f MB", bytes / 1e6);
  }

  static void copyTree(Path from, Path to) throws IOException {
    try (Stream<Path> s = Files.walk(from)) {
      for (Path f : s.toList()) {
        Path t = to.resolve(from.relativize(f).toString());
        if (Files.isDirectory(f)) {
          Files.createDirectories(t);
        } else {
          Files.copy(f, t, StandardCopyOption.REPLACE_EXISTING);
        }
      }
    }
  }

  static void deleteTree(Path dir) throws IOException {
    if (!Files.exists(dir)) {
      return;
    }
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.sorted((x, y) -> y.getNameCount() - x.getNameCount()).toList()) {
        Files.delete(p);
      }
    }
  }

  static void log(String msg) {
    System.out.println("[package] " + msg);
  }
}
