import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Prints PIT's mutation score per package from target/pit-reports/mutations.xml and checks the
 * goals of issue 31: at least 85 % of mutants killed in robot, motion, collision and program, 75 %
 * in sim. Score = mutants detected (killed or timed out) / all mutants, no-coverage counted as
 * survived, as PIT's own "mutation score". Exit 1 when a package with a goal is under it (unless
 * {@code --warn} or PIT_GOALS=warn), 2 when the report cannot be read. Run by the mutation profile after PIT:
 * {@code java .ci/PitSummary.java target/pit-reports/mutations.xml [--warn]}.
 */
public class PitSummary {
    static final Map<String, Integer> GOALS = Map.of(
            "org.robotrun.robot", 85, "org.robotrun.motion", 85, "org.robotrun.collision", 85,
            "org.robotrun.program", 85, "org.robotrun.sim", 75);

    public static void main(String[] args) throws Exception {
        if (args.length < 1) {
            System.err.println("usage: java .ci/PitSummary.java mutations.xml [--warn]");
            System.exit(2);
        }
        boolean warnOnly = (args.length > 1 && args[1].equals("--warn")) || "warn".equals(System.getenv("PIT_GOALS"));
        Path xml = Path.of(args[0]);
        if (!Files.isReadable(xml)) {
            System.err.println("pit-summary: " + xml + " not found (did PIT run?)");
            System.exit(2);
        }
        String text = Files.readString(xml);
        Pattern mutation = Pattern.compile(
                "<mutation\\b[^>]*\\bstatus='([A-Z_]+)'[^>]*>.*?<mutatedClass>([^<]+)</mutatedClass>", Pattern.DOTALL);
        Map<String, int[]> byPackage = new TreeMap<>(); // total, detected, noCoverage
        Matcher m = mutation.matcher(text);
        while (m.find()) {
            String status = m.group(1);
            String cls = m.group(2);
            int dot = cls.lastIndexOf('.');
            String pkg = dot < 0 ? "" : cls.substring(0, dot);
            int[] c = byPackage.computeIfAbsent(pkg, k -> new int[3]);
            c[0]++;
            if (status.equals("KILLED") || status.equals("TIMED_OUT") || status.equals("MEMORY_ERROR")) c[1]++;
            if (status.equals("NO_COVERAGE")) c[2]++;
        }
        if (byPackage.isEmpty()) {
            System.err.println("pit-summary: no mutations in " + xml);
            System.exit(2);
        }
        System.out.println("pit-summary: mutation score per package (killed / all; goal from issue 31)");
        boolean under = false;
        int total = 0, detected = 0;
        for (var e : byPackage.entrySet()) {
            int[] c = e.getValue();
            total += c[0];
            detected += c[1];
            double pct = 100.0 * c[1] / c[0];
            Integer goal = GOALS.get(e.getKey());
            String verdict = goal == null ? "" : pct + 1e-9 >= goal ? "  goal " + goal + "% met" : "  UNDER goal " + goal + "%";
            if (goal != null && pct + 1e-9 < goal) under = true;
            System.out.printf("  %-28s %5d/%-5d %5.1f%%  (no coverage %d)%s%n", e.getKey(), c[1], c[0], pct, c[2], verdict);
        }
        System.out.printf("  %-28s %5d/%-5d %5.1f%%%n", "all", detected, total, 100.0 * detected / total);
        if (under && !warnOnly) {
            System.err.println("pit-summary: a package is under its mutation-score goal (see above)");
            System.exit(1);
        }
    }
}
