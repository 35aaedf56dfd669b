package org.robotrun.io;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/**
 * The child JVM of {@link WorkspaceKillTest}: opens (or creates) the workspace in args[0] and
 * edits it forever, autosaving as the window does. Edit i adds program P{i} (three lines that name i) and
 * sets R[1] = i; it continues after the last edit found on disk. Prints each edit number.
 */
public final class WorkspaceEditLoop {
  private WorkspaceEditLoop() {}

  static Program program(int i) {
    List<Instruction> lines = new ArrayList<>();
    for (int k = 1; k <= 3; k++) {
      lines.add(new Instruction.Comment("edit " + i + " line " + k));
    }
    return Program.of("P" + i, lines);
  }

  public static void main(String[] args) throws Exception {
    Path dir = Path.of(args[0]);
    Scenario cell = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of(args[1]))).scenario();
    Workspace ws = Workspace.open(dir, cell);
    Map<String, Program> programs = new LinkedHashMap<>();
    ws.programs().stream().sorted((a, b) -> Integer.compare(Integer.parseInt(a.name().substring(1)),
        Integer.parseInt(b.name().substring(1)))).forEach(p -> programs.put(p.name(), p));
    int[] edit = {programs.size()};
    Autosave autosave = new Autosave(ws, () -> {
      TreeMap<Integer, SavedState.Register> r = new TreeMap<>();
      r.put(1, new SavedState.Register(edit[0], true));
      SavedState st = new SavedState(-1, -1, -1, r, new TreeMap<>(), new TreeMap<>(), new TreeMap<>(), "");
      try {
        return new WorkspaceSnapshot(ScenarioWriter.toJson(ws.scenario(), Optional.of(st), ws.folder()), programs);
      } catch (java.io.IOException e) {
        throw new java.io.UncheckedIOException(e);
      }
    }, m -> System.err.println(m));
    System.out.println("ready " + edit[0]);
    System.out.flush();
    if (args.length > 2 && args[2].equals("--exit")) {
      autosave.close();  // a clean exit (the warm-up run that writes the class-data archive)
      ws.close();
      return;
    }
    while (true) {
      edit[0]++;
      programs.put("P" + edit[0], program(edit[0]));
      autosave.poll(System.nanoTime());
      System.out.println(edit[0]);
      // About 200 new program files a second, far more than a student makes. (Before a save synced
      // the folder once per batch instead of once per file, 500 a second missed the 2 s bound on
      // a busy disk; with the batch it held in a local run.)
      Thread.sleep(5);
    }
  }
}
