package org.robotrun.io;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/**
 * A student's workspace: a folder holding {@code cell.json} (the cell as it is now and the
 * controller's state, docs/scenario-format.md) and {@code programs/NAME.LS}, one FANUC .LS file
 * per program. Nothing else is needed to restore the work.
 *
 * <p>Opening takes a lock ({@value #LOCK} in the folder, an OS lock that a crash releases): a
 * second window on the same folder opens it read-only and says so. A file that cannot be read
 * is reported (file:line for a program, JSON path for {@code cell.json}) and never written
 * over; the rest opens. {@link #save} writes only what changed since the last save, each file
 * through {@link AtomicFiles}, so a crash at any moment leaves every file whole.
 *
 * <p>Thread use: {@link #open} and the getters on any thread; {@link #save} and
 * {@link #recordExternalState} on one writer thread at a time (the {@link Autosave} thread).
 */
public final class Workspace implements AutoCloseable {
  public static final String CELL = "cell.json";
  public static final String PROGRAMS = "programs";
  /** The folder of the cell editor's other named scenarios, one {@code NAME.json} each (the active one is {@code cell.json}). */
  public static final String SCENARIOS = "scenarios";
  /** What a scenario file in {@link #SCENARIOS} may be called (also what a hand-in accepts). */
  public static final java.util.regex.Pattern SCENARIO_FILE = java.util.regex.Pattern.compile("[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}\\.json");
  public static final String LOCK = ".robotrun.lock";
  /** Largest program file read (the .LS reader has no use for more). */
  public static final long MAX_PROGRAM_BYTES = 8L << 20;

  private final Path dir;
  private final FileChannel lockChannel;
  private final FileLock lock;
  private final String readOnlyReason;
  private final Scenario scenario;
  private final Optional<SavedState> state;
  private final List<Program> programs;
  /** Programs of the robots after the first, by robot name (programs/ROBOT/NAME.LS). */
  private final Map<String, List<Program>> robotPrograms = new LinkedHashMap<>();
  private final List<String> problems;
  private final boolean cellBlocked;
  /** Opened from a hand-in: the files its cells name are read only from inside it. */
  private boolean handIn;
  /** Read-only because another RobotRun holds the lock (it may let go soon). */
  private boolean lockBusy;
  /** The other named scenarios read from {@code scenarios/}, in file-name order. */
  private List<Scenario> otherScenarios = List.of();
  /** Scenario files that could not be read (or repeat a name): never written over or deleted. */
  private final Set<String> blockedScenarios = ConcurrentHashMap.newKeySet();
  /** Scenario file name → the text it holds as last read or written here. */
  private final Map<String, String> writtenScenarios = new ConcurrentHashMap<>();
  /** Program files that could not be read: never written over or deleted. */
  private final Set<Path> blocked = ConcurrentHashMap.newKeySet();
  /** Program name → its file (as loaded, or programs/NAME.LS once written). */
  private final Map<String, Path> fileOf = new ConcurrentHashMap<>();
  /** What is on disk as this workspace last read or wrote it: file → size and modification time. */
  private final Map<Path, Stamp> stamps = new ConcurrentHashMap<>();
  // What the files hold now (written by the writer thread).
  private volatile String writtenCell;
  private final Map<String, Program> writtenPrograms = new ConcurrentHashMap<>();

  /** A file's size and modification time, to notice an edit made outside RobotRun. */
  record Stamp(long size, FileTime modified) {
    static Stamp of(Path file) {
      try {
        return new Stamp(Files.size(file), Files.getLastModifiedTime(file));
      } catch (IOException e) {
        return new Stamp(-1, FileTime.fromMillis(0));
      }
    }
  }

  private Workspace(Path dir, FileChannel lockChannel, FileLock lock, String readOnlyReason, Scenario scenario,
      Optional<SavedState> state, List<Program> programs, List<String> problems, boolean cellBlocked) {
    this.dir = dir;
    this.lockChannel = lockChannel;
    this.lock = lock;
    this.readOnlyReason = readOnlyReason;
    this.scenario = scenario;
    this.state = state;
    this.programs = List.copyOf(programs);
    this.problems = java.util.Collections.unmodifiableList(problems);  // open() adds the scenarios' before returning
    this.cellBlocked = cellBlocked;
  }

  /**
   * Opens the workspace in {@code dir}, creating it (the folder, {@code programs/} and a
   * {@code cell.json} of {@code newCell}) when the folder is missing or empty.
   *
   * @param newCell the cell of a new workspace, and the cell used when {@code cell.json} cannot be read
   * @throws WorkspaceException when the folder is not a workspace or cannot be created
   */
  public static Workspace open(Path dir, Scenario newCell) throws WorkspaceException {
    return open(dir, newCell, false);
  }

  /**
   * Opens the workspace as {@link #open(Path, Scenario)} does; with {@code readOnly} no lock is
   * taken and nothing is ever written (a hand-in being run, a second look).
   */
  public static Workspace open(Path dir, Scenario newCell, boolean readOnly) throws WorkspaceException {
    return open(dir, newCell, readOnly, false);
  }

  /**
   * Opens an unpacked hand-in read-only: as {@link #open(Path, Scenario, boolean)}, but the cell
   * files may name meshes and programs only inside the hand-in
   * ({@link ScenarioReader#readHandInCell}).
   */
  public static Workspace openHandIn(Path dir, Scenario newCell) throws WorkspaceException {
    return open(dir, newCell, true, true);
  }

  private static Workspace open(Path dir, Scenario newCell, boolean readOnly, boolean handIn) throws WorkspaceException {
    Path abs = dir.toAbsolutePath().normalize();
    Path cell = abs.resolve(CELL);
    try {
      if (Files.exists(abs) && !Files.isDirectory(abs)) {
        throw new WorkspaceException(abs + ": not a folder (a workspace is a folder with cell.json and programs/)");
      }
      if (!Files.exists(cell)) {
        if (readOnly) {
          throw new WorkspaceException(abs + ": not a workspace (no " + CELL + ")");
        }
        create(abs, newCell);
      }
    } catch (AccessDeniedException e) {
      throw new WorkspaceException(abs + ": cannot create the workspace here (permission denied)");
    } catch (IOException e) {
      throw new WorkspaceException(abs + ": cannot create the workspace (" + describe(e) + ")");
    }
    FileChannel channel = null;
    FileLock lock = null;
    String readOnlyReason = !readOnly ? "" : handIn
        ? "a hand-in opens read-only (File > Save a copy as... gives a workspace to edit)" : "opened read-only";
    boolean lockBusy = false;
    String lockProblem = readOnly ? "" : specialLock(abs.resolve(LOCK));
    if (!lockProblem.isEmpty()) {
      // never opened: a FIFO would block the open for ever, a device or a link is not ours to lock
      readOnlyReason = lockProblem + ": opened read-only, nothing is saved";
    } else if (!readOnly) {
      try {
        channel = FileChannel.open(abs.resolve(LOCK), StandardOpenOption.CREATE, StandardOpenOption.WRITE,
            LinkOption.NOFOLLOW_LINKS);
        lock = channel.tryLock();
        if (lock == null) {
          lockBusy = true;
          readOnlyReason = "another RobotRun window has this workspace open: opened read-only, nothing is saved";
        }
      } catch (OverlappingFileLockException e) {
        lockBusy = true;
        readOnlyReason = "this workspace is already open in this RobotRun: opened read-only, nothing is saved";
      } catch (IOException e) {
        readOnlyReason = "the folder is not writable (" + describe(e) + "): opened read-only, nothing is saved";
      }
      if (lock == null && channel != null) {
        closeQuietly(channel);
        channel = null;
      }
    }
    List<String> problems = new ArrayList<>();
    Scenario scenario = newCell;
    Optional<SavedState> state = Optional.empty();
    boolean cellBlocked = false;
    switch (handIn ? ScenarioReader.readHandInCell(cell) : ScenarioReader.readCell(cell)) {
      case CellLoad.Loaded l -> {
        scenario = l.scenario();
        state = l.state();
      }
      case CellLoad.Failed f -> {
        cellBlocked = true;
        problems.add(f.message() + "\n" + cell + " is kept as it is and not saved over; the default cell is shown. "
            + "Fix the file (or move it away) and open the workspace again.");
      }
    }
    Map<String, Path> fileOf = new LinkedHashMap<>();
    List<Program> programs = new ArrayList<>();
    Set<Path> blocked = new java.util.HashSet<>();
    Path programDir = abs.resolve(PROGRAMS);
    for (Path file : programFiles(programDir, problems)) {
      Optional<Program> p = readProgram(file, problems);
      if (p.isEmpty()) {
        blocked.add(file);
        continue;
      }
      Path first = fileOf.putIfAbsent(p.get().name(), file);
      if (first != null) {
        problems.add(file + ":1: program " + p.get().name() + " is also in " + first.getFileName()
            + "; this file is not loaded and is kept as it is");
        blocked.add(file);
        continue;
      }
      programs.add(p.get());
    }
    // Every robot after the first keeps its programs in a folder of its own: programs/ROBOT/NAME.LS,
    // known here as "ROBOT/NAME".
    Map<String, List<Program>> perRobot = new LinkedHashMap<>();
    for (int i = 1; i < scenario.robots().size(); i++) {
      String robot = scenario.robots().get(i).name();
      String folder = robotFolder(robot);
      List<Program> own = new ArrayList<>();
      for (Path file : programFiles(programDir.resolve(folder), problems)) {
        Optional<Program> p = readProgram(file, problems);
        if (p.isEmpty()) {
          blocked.add(file);
          continue;
        }
        Path first = fileOf.putIfAbsent(folder + "/" + p.get().name(), file);
        if (first != null) {
          problems.add(file + ":1: program " + p.get().name() + " is also in " + first.getFileName()
              + "; this file is not loaded and is kept as it is");
          blocked.add(file);
          continue;
        }
        own.add(p.get());
      }
      perRobot.put(robot, own);
    }
    Workspace ws = new Workspace(abs, channel, lock, readOnlyReason, scenario, state, programs, problems, cellBlocked);
    ws.handIn = handIn;
    ws.lockBusy = lockBusy;
    if (lock != null) {
      removeStaleTemporaryFiles(abs, scenario);
    }
    ws.readScenarios(problems);
    ws.robotPrograms.putAll(perRobot);
    perRobot.forEach((robot, ps) -> ps.forEach(p -> ws.writtenPrograms.put(robotFolder(robot) + "/" + p.name(), p)));
    ws.blocked.addAll(blocked);
    ws.fileOf.putAll(fileOf);
    for (Program p : programs) {
      ws.writtenPrograms.put(p.name(), p);
    }
    if (!cellBlocked) {
      try {
        ws.writtenCell = BoundedFiles.readUtf8(cell, ScenarioReader.MAX_FILE_BYTES, "cell files");
      } catch (IOException | FileFormatException e) {
        // then the first save writes it
      }
    }
    try (Stream<Path> all = Files.exists(programDir) ? Files.list(programDir) : Stream.empty()) {
      all.forEach(f -> ws.stamps.put(f, Stamp.of(f)));
    } catch (IOException e) {
      // stamps only serve to notice outside edits
    }
    return ws;
  }

  /**
   * Reads {@code scenarios/*.json}. A file that cannot be read, or names a scenario another file
   * already has, is reported and kept as it is. A file naming the active scenario is what an
   * interrupted switch left (the same scenario is in {@code cell.json}): not loaded, and removed
   * at the next save.
   */
  private void readScenarios(List<String> problems) {
    Path folder = dir.resolve(SCENARIOS);
    if (!Files.isDirectory(folder)) {
      return;
    }
    List<Path> files;
    try (Stream<Path> s = Files.list(folder)) {
      files = s.filter(f -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".json"))
          .filter(Files::isRegularFile).sorted().toList();
    } catch (IOException e) {
      problems.add(folder + ": cannot list the scenarios (" + describe(e) + ")");
      return;
    }
    List<Scenario> out = new ArrayList<>();
    Map<String, Path> names = new HashMap<>();
    for (Path f : files) {
      String file = f.getFileName().toString();
      if (!SCENARIO_FILE.matcher(file).matches()) {
        problems.add(f + ": not loaded: a scenario file name is letters, digits, '_', '.' and '-' ending in .json"
            + " (at most 69 characters); the file is kept as it is");
        blockedScenarios.add(file);
        continue;
      }
      switch (handIn ? ScenarioReader.readHandInCell(f) : ScenarioReader.readCell(f)) {
        case CellLoad.Failed failed -> {
          problems.add(failed.message() + "\n" + f + " is kept as it is and not loaded; fix it and open the workspace again.");
          blockedScenarios.add(file);
        }
        case CellLoad.Loaded l -> {
          Scenario sc = l.scenario().name().isBlank() ? renamed(l.scenario(), file.substring(0, file.length() - 5))
              : l.scenario();
          if (!cellBlocked && sc.name().equals(scenario.name())) {
            continue;  // left by an interrupted switch: cell.json holds this scenario
          }
          Path first = names.putIfAbsent(sc.name(), f);
          if (first != null) {
            problems.add(f + ": scenario '" + sc.name() + "' is also in " + first.getFileName()
                + "; this file is not loaded and is kept as it is");
            blockedScenarios.add(file);
            continue;
          }
          try {
            writtenScenarios.put(file, BoundedFiles.readUtf8(f, ScenarioReader.MAX_FILE_BYTES, "scenario files"));
          } catch (IOException e) {
            // then the next save writes it again
          }
          out.add(sc);
        }
      }
    }
    otherScenarios = List.copyOf(out);
  }

  /** {@code s} under another name. */
  static Scenario renamed(Scenario s, String name) {
    return s.withName(name, s.description());
  }

  /**
   * The file each scenario is saved in: its name with every character other than letters,
   * digits, '_', '.' and '-' made '_' (so any name gives a file name every system accepts), a
   * number added when two names give the same file (letter case ignored, as on Windows and
   * macOS) or a file that could not be read has it.
   */
  public static Map<String, Scenario> scenarioFileNames(List<Scenario> scenarios, Set<String> taken) {
    Map<String, Scenario> out = new LinkedHashMap<>();
    Set<String> used = new java.util.HashSet<>();
    taken.forEach(t -> used.add(t.toLowerCase(Locale.ROOT)));
    for (Scenario s : scenarios) {
      String stem = s.name().isBlank() ? "unnamed" : s.name().strip().replaceAll("[^A-Za-z0-9_.\\-]", "_");
      if (!Character.isLetterOrDigit(stem.charAt(0)) && stem.charAt(0) != '_') {
        stem = "_" + stem;
      }
      stem = stem.length() > 60 ? stem.substring(0, 60) : stem;
      String file = stem + ".json";
      for (int n = 2; used.contains(file.toLowerCase(Locale.ROOT)); n++) {
        file = stem + "-" + n + ".json";
      }
      used.add(file.toLowerCase(Locale.ROOT));
      out.put(file, s);
    }
    return out;
  }

  private static void create(Path abs, Scenario newCell) throws IOException, WorkspaceException {
    if (Files.isDirectory(abs)) {
      try (Stream<Path> s = Files.list(abs)) {
        List<String> names = s.map(p -> p.getFileName().toString()).filter(n -> !n.equals(LOCK)).toList();
        if (!names.isEmpty() && !names.contains(PROGRAMS)) {
          throw new WorkspaceException(abs + ": the folder is not empty and has no " + CELL
              + "; a new workspace needs an empty or new folder");
        }
      }
    }
    Files.createDirectories(abs.resolve(PROGRAMS));
    String created = Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
    SavedState fresh = SavedState.fresh(created);
    Path cell = abs.resolve(CELL);
    AtomicFiles.write(cell, ScenarioWriter.readableBytes(ScenarioWriter.toJson(newCell, Optional.of(fresh), abs), cell));
  }

  /** The .LS files in {@code programs/}, by name. */
  private static List<Path> programFiles(Path programDir, List<String> problems) {
    if (!Files.isDirectory(programDir)) {
      return List.of();
    }
    try (Stream<Path> s = Files.list(programDir)) {
      return s.filter(f -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".ls"))
          .filter(Files::isRegularFile).sorted().toList();
    } catch (IOException e) {
      problems.add(programDir + ": cannot list the programs (" + describe(e) + ")");
      return List.of();
    }
  }

  /** Reads one program file; a problem (file:line) and empty when it cannot be used. */
  static Optional<Program> readProgram(Path file, List<String> problems) {
    try {
      long size = Files.size(file);
      if (size > MAX_PROGRAM_BYTES) {
        problems.add(file + ":1: the file is " + size + " bytes; programs are limited to " + MAX_PROGRAM_BYTES
            + " bytes. It is kept as it is and not loaded.");
        return Optional.empty();
      }
      LsReadResult r = LsReader.readCheckingFileName(file);
      List<Diagnostic> errors = r.diagnostics().stream().filter(Diagnostic::isError).toList();
      if (!errors.isEmpty() || r.program() == null) {
        StringBuilder sb = new StringBuilder();
        errors.stream().limit(5).forEach(d -> sb.append(d).append('\n'));
        if (errors.size() > 5) {
          sb.append("(").append(errors.size() - 5).append(" more errors)\n");
        }
        sb.append(file.getFileName()).append(" is kept as it is and not loaded; fix it and open the workspace again.");
        problems.add(sb.toString());
        return Optional.empty();
      }
      return Optional.of(r.program());
    } catch (NoSuchFileException e) {
      problems.add(file + ": the file was removed while it was being read");
      return Optional.empty();
    } catch (IOException e) {
      problems.add(file + ": cannot read (" + describe(e) + "); it is kept as it is and not loaded");
      return Optional.empty();
    }
  }

  // ---- what was opened ------------------------------------------------------------------------

  /** The workspace folder (absolute). */
  public Path folder() {
    return dir;
  }

  /** The folder's name, for the window title. */
  public String name() {
    return dir.getFileName() == null ? dir.toString() : dir.getFileName().toString();
  }

  /** The cell: from {@code cell.json}, or the new-workspace cell when that file could not be read. */
  public Scenario scenario() {
    return scenario;
  }

  /** The other named scenarios (the cell editor's list besides the active one), from {@code scenarios/}. */
  public List<Scenario> otherScenarios() {
    return otherScenarios;
  }

  /** The controller state saved in {@code cell.json}, if any. */
  public Optional<SavedState> state() {
    return state;
  }

  /** The programs that were read, in file-name order (the first robot's). */
  public List<Program> programs() {
    return programs;
  }

  /** The programs read for robot {@code robot} (one after the first), in file-name order; empty for any other. */
  public List<Program> programs(String robot) {
    return robotPrograms.getOrDefault(robot, List.of());
  }

  /**
   * The folder under {@code programs/} of a robot after the first: its name, with any character
   * other than letters, digits, '-', '_' and '.' replaced by '_', a leading '.' or '-' prefixed
   * with '_', at most 64 characters (as a hand-in's entry names allow).
   */
  public static String robotFolder(String robot) {
    String f = robot.replaceAll("[^A-Za-z0-9._-]", "_");
    if (f.isEmpty() || f.startsWith(".") || f.startsWith("-")) {
      f = "_" + f;
    }
    return f.length() > 64 ? f.substring(0, 64) : f;
  }

  /** What could not be read or done while opening, each a message for the user; empty when all went well. */
  public List<String> problems() {
    return problems;
  }

  /** Whether nothing will be written, and why ("" when writable). */
  public boolean readOnly() {
    return !readOnlyReason.isEmpty();
  }

  /** Whether this is read-only only because another RobotRun has the workspace open. */
  public boolean lockBusy() {
    return lockBusy;
  }

  /**
   * Why {@code lock} cannot be the lock file (a FIFO, a device, a socket, a folder, a symbolic
   * link), found without opening it; "" when it is a regular file or missing.
   */
  static String specialLock(Path lock) {
    java.nio.file.attribute.BasicFileAttributes a;
    try {
      a = Files.readAttributes(lock, java.nio.file.attribute.BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
    } catch (IOException e) {
      return "";  // missing (it is created) or unreadable (the open says why)
    }
    if (a.isRegularFile()) {
      return "";
    }
    String kind = a.isSymbolicLink() ? "a symbolic link" : BoundedFiles.kind(lock, a);
    return "the lock file " + lock + " is " + kind + ", not a regular file (remove it)";
  }

  /** Age after which a temporary file of an interrupted save is removed by the workspace's writer. */
  static final java.time.Duration STALE_TEMP_AGE = java.time.Duration.ofSeconds(10);

  /**
   * Removes the temporary files a killed save left ({@code .NAME.0123456789ab.tmp}, written by
   * {@link AtomicFiles}) from the workspace's folders. Called only by the lock's holder, the
   * one writer, for files older than {@link #STALE_TEMP_AGE}; best effort.
   */
  private static void removeStaleTemporaryFiles(Path abs, Scenario scenario) {
    List<Path> folders = new ArrayList<>(List.of(abs, abs.resolve(PROGRAMS), abs.resolve(SCENARIOS)));
    for (int i = 1; i < scenario.robots().size(); i++) {
      folders.add(abs.resolve(PROGRAMS).resolve(robotFolder(scenario.robots().get(i).name())));
    }
    java.time.Instant before = java.time.Instant.now().minus(STALE_TEMP_AGE);
    for (Path folder : folders) {
      if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
        continue;
      }
      try (Stream<Path> s = Files.list(folder)) {
        for (Path f : s.toList()) {
          if (AtomicFiles.isTemporaryName(f.getFileName().toString())
              && Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS)
              && Files.getLastModifiedTime(f, LinkOption.NOFOLLOW_LINKS).toInstant().isBefore(before)) {
            Files.deleteIfExists(f);
          }
        }
      } catch (IOException | RuntimeException e) {
        // a leftover costs disk space only
      }
    }
  }

  public String readOnlyReason() {
    return readOnlyReason;
  }

  /** Whether {@code cell.json} could not be read (and so is never written). */
  public boolean cellBlocked() {
    return cellBlocked;
  }

  /** The file that holds (or will hold) program {@code name}. */
  public Path programFile(String name) {
    return fileOf.getOrDefault(name, dir.resolve(PROGRAMS).resolve(name + ".LS"));
  }

  // ---- saving ---------------------------------------------------------------------------------

  /**
   * Writes what changed since the last save: {@code cell.json} when its text differs, each
   * program that is new or a different object than the one last written, and removes the files
   * of deleted programs. Files that could not be read at open are left alone.
   *
   * @return the files written or removed
   * @throws IOException naming the file, after writing what could be written
   */
  public List<Path> save(WorkspaceSnapshot snap) throws IOException {
    if (readOnly()) {
      return List.of();
    }
    List<Path> touched = new ArrayList<>();
    IOException first = null;
    Path programDir = dir.resolve(PROGRAMS);
    // The changed programs, in the order given, written together (one folder sync); a failure
    // leaves the rest for the next save.
    List<Map.Entry<Path, byte[]>> batch = new ArrayList<>();
    List<Map.Entry<String, Program>> batchPrograms = new ArrayList<>();
    for (Map.Entry<String, Program> e : snap.programs().entrySet()) {
      String name = e.getKey();
      if (writtenPrograms.get(name) == e.getValue()) {
        continue;
      }
      Path file = programFile(name);
      // An unreadable file keeps its name: a program of that name goes beside it (NAME-2.LS ...),
      // which the .LS reader loads as NAME with a warning about the file name.
      for (int n = 2; blocked.contains(file); n++) {
        file = programDir.resolve(name + "-" + n + ".LS");
      }
      batch.add(Map.entry(file, LsWriter.write(e.getValue()).getBytes(StandardCharsets.UTF_8)));
      batchPrograms.add(e);
    }
    Set<Path> folders = new java.util.LinkedHashSet<>();
    batch.forEach(e -> folders.add(e.getKey().getParent()));
    for (Path folder : folders) {
      try {
        Files.createDirectories(folder);
      } catch (IOException ex) {
        first = first == null ? failure(folder, ex) : first;
      }
    }
    for (int i = 0; i < batch.size() && first == null; i++) {
      Path file = batch.get(i).getKey();
      try {
        AtomicFiles.writeLeavingFolderSync(file, batch.get(i).getValue());
      } catch (IOException ex) {
        first = failure(file, ex);
        break;
      }
      String name = batchPrograms.get(i).getKey();
      writtenPrograms.put(name, batchPrograms.get(i).getValue());
      fileOf.put(name, file);
      stamps.put(file, Stamp.of(file));
      touched.add(file);
    }
    if (!touched.isEmpty()) {
      for (Path folder : folders) {
        AtomicFiles.syncFolder(folder);  // once per folder for the whole batch, before cell.json names its results
      }
    }
    for (String name : List.copyOf(writtenPrograms.keySet())) {
      if (snap.programs().containsKey(name)) {
        continue;
      }
      Path file = programFile(name);
      try {
        Files.deleteIfExists(file);
        writtenPrograms.remove(name);
        fileOf.remove(name);
        stamps.remove(file);
        touched.add(file);
      } catch (IOException ex) {
        first = first == null ? failure(file, ex) : first;
      }
    }
    // The other scenarios before cell.json and the removals after it: a crash in between leaves
    // a scenario twice (the file copy is dropped at open), never none.
    Map<String, String> wanted = new LinkedHashMap<>();
    boolean scenarioFailed = false;
    if (snap.otherScenarios().isPresent()) {
      Path folder = dir.resolve(SCENARIOS);
      for (Map.Entry<String, Scenario> e : scenarioFileNames(snap.otherScenarios().get(), blockedScenarios).entrySet()) {
        String text = ScenarioWriter.toJson(e.getValue(), folder);
        wanted.put(e.getKey(), text);
        if (scenarioFailed || text.equals(writtenScenarios.get(e.getKey()))) {
          continue;
        }
        Path file = folder.resolve(e.getKey());
        try {
          Files.createDirectories(folder);
          // never a scenario file RobotRun cannot read back (the same guard as cell.json below)
          AtomicFiles.write(file, ScenarioWriter.readableBytes(text, file));
          writtenScenarios.put(e.getKey(), text);
          touched.add(file);
        } catch (IOException ex) {
          first = first == null ? failure(file, ex) : first;
          scenarioFailed = true;
        }
      }
    }
    // cell.json only once the scenario it replaces is safe in scenarios/ (a switch)
    if (!cellBlocked && !snap.cellJson().equals(writtenCell) && !scenarioFailed) {
      Path cell = dir.resolve(CELL);
      try {
        AtomicFiles.write(cell, ScenarioWriter.readableBytes(snap.cellJson(), cell));
        writtenCell = snap.cellJson();
        touched.add(cell);
      } catch (IOException ex) {
        first = first == null ? failure(cell, ex) : first;
      }
    }
    if (snap.otherScenarios().isPresent() && !scenarioFailed && snap.cellJson().equals(writtenCell)) {
      Path folder = dir.resolve(SCENARIOS);
      for (String file : scenarioFilesOnDisk(folder)) {
        if (wanted.containsKey(file) || blockedScenarios.contains(file)) {
          continue;
        }
        try {
          Files.deleteIfExists(folder.resolve(file));
          writtenScenarios.remove(file);
          touched.add(folder.resolve(file));
        } catch (IOException ex) {
          first = first == null ? failure(folder.resolve(file), ex) : first;
        }
      }
    }
    if (first != null) {
      throw first;
    }
    return touched;
  }

  /** The .json files in {@code scenarios/} (none when the folder is missing or cannot be listed). */
  private static List<String> scenarioFilesOnDisk(Path folder) {
    if (!Files.isDirectory(folder)) {
      return List.of();
    }
    try (Stream<Path> s = Files.list(folder)) {
      return s.map(p -> p.getFileName().toString()).filter(n -> n.toLowerCase(Locale.ROOT).endsWith(".json")).sorted().toList();
    } catch (IOException e) {
      return List.of();
    }
  }

  /** Marks {@code cellJson} as what {@code cell.json} holds (read at open), so it is not rewritten needlessly. */
  public void assumeWrittenCell(String cellJson) {
    writtenCell = cellJson;
  }

  private static IOException failure(Path file, IOException e) {
    return new IOException("cannot save " + file + ": " + describe(e), e);
  }

  /** A short reason for an I/O failure, in words a student can act on. */
  public static String describe(IOException e) {
    if (e instanceof UnreadableFileException u) {
      return u.file() + ": " + u.getMessage();  // a file read on the way: say which
    }
    String m = e.getMessage() == null ? "" : e.getMessage();
    if (e instanceof AccessDeniedException || m.contains("Permission denied") || m.contains("Read-only file system")) {
      return m.contains("Read-only") ? "the disk is read-only" : "permission denied";
    }
    if (m.contains("No space left") || m.contains("Disk quota")) {
      return "the disk is full";
    }
    if (e instanceof NoSuchFileException) {
      return "the folder " + m + " no longer exists";
    }
    return m.isEmpty() ? e.getClass().getSimpleName() : m;
  }

  // ---- edits made outside ---------------------------------------------------------------------

  /**
   * A program file that changed on disk since this workspace last read or wrote it.
   *
   * @param programName the program the file held, "" for a file new to this workspace
   * @param deleted whether the file is gone (it is written again at the next save)
   */
  public record ExternalChange(Path file, String programName, boolean deleted) {}

  /** Whether {@code p} is exactly what was last read from or written to its file (not edited since). */
  public boolean isSaved(String name, Program p) {
    return writtenPrograms.get(name) == p;
  }

  /**
   * The program files changed, added or removed on disk by someone else since they were last
   * read or written here (a text editor). Reads only file sizes and times.
   */
  public List<ExternalChange> externalChanges() {
    List<ExternalChange> out = new ArrayList<>();
    Path programDir = dir.resolve(PROGRAMS);
    Map<Path, String> nameOf = new HashMap<>();
    fileOf.forEach((name, file) -> nameOf.put(file, name));
    List<Path> watched = new ArrayList<>(programFiles(programDir, new ArrayList<>()));
    for (int i = 1; i < scenario.robots().size(); i++) {
      watched.addAll(programFiles(programDir.resolve(robotFolder(scenario.robots().get(i).name())), new ArrayList<>()));
    }
    for (Path f : watched) {
      Stamp before = stamps.get(f);
      if (before == null || !before.equals(Stamp.of(f))) {
        out.add(new ExternalChange(f, nameOf.getOrDefault(f, ""), false));
      }
    }
    // Deleted underneath: forget that they were written, so the next save puts them back.
    for (Map.Entry<String, Path> e : fileOf.entrySet()) {
      if (!Files.exists(e.getValue()) && writtenPrograms.containsKey(e.getKey())) {
        writtenPrograms.remove(e.getKey());
        stamps.remove(e.getValue());
        out.add(new ExternalChange(e.getValue(), e.getKey(), true));
      }
    }
    if (!cellBlocked && !Files.exists(dir.resolve(CELL))) {
      writtenCell = null;
    }
    return out;
  }

  /** Reads a changed file again: the program, or empty with a message added to {@code problems}. */
  public Optional<Program> reread(Path file, List<String> problems) {
    Optional<Program> p = readProgram(file, problems);
    stamps.put(file, Stamp.of(file));
    if (p.isPresent()) {
      blocked.remove(file);
      String key = robotFolderOf(file).map(f -> f + "/" + p.get().name()).orElse(p.get().name());
      fileOf.put(key, file);
      writtenPrograms.put(key, p.get());
    } else {
      blocked.add(file);
    }
    return p;
  }

  /** The robot folder ({@link #robotFolder}) a program file lies in, or empty for {@code programs/} itself (the first robot). */
  public Optional<String> robotFolderOf(Path file) {
    Path parent = file.toAbsolutePath().normalize().getParent();
    Path programDir = dir.resolve(PROGRAMS);
    if (parent == null || parent.equals(programDir) || !programDir.equals(parent.getParent())) {
      return Optional.empty();
    }
    return Optional.of(parent.getFileName().toString());
  }

  /** Forgets a changed file's new stamp without reading it (the user chose to keep the program in the window). */
  public void keepOurs(Path file) {
    stamps.put(file, new Stamp(-2, FileTime.fromMillis(0)));
    blocked.remove(file);
    String name = fileOf.entrySet().stream().filter(e -> e.getValue().equals(file)).map(Map.Entry::getKey)
        .findFirst().orElse(null);
    if (name != null) {
      writtenPrograms.remove(name);  // written again at the next save
    }
  }

  @Override
  public void close() {
    try {
      if (lock != null) {
        lock.release();
      }
    } catch (IOException e) {
      // the OS releases it when the process ends
    }
    if (lockChannel != null) {
      closeQuietly(lockChannel);
    }
  }

  private static void closeQuietly(FileChannel c) {
    try {
      c.close();
    } catch (IOException e) {
      // nothing left to do
    }
  }
}
