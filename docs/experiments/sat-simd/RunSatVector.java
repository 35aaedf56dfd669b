import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.robotrun.collision.SeparatingAxisTest;

/**
 * EXPERIMENT, not part of the build: checks {@link SatVector256} against the product's scalar
 * test on a {@code bench collision} pairs file and times both in one JVM, alternating rounds.
 * Usage: see README.md.
 */
final class RunSatVector {
  private RunSatVector() {}

  public static void main(String[] args) throws Exception {
    List<String> lines = Files.readAllLines(Path.of(args[0]));
    int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 7;
    int n = lines.size() - 1;
    double[] a = new double[n * 15];
    double[] b = new double[n * 15];
    for (int i = 0; i < n; i++) {
      String[] f = lines.get(i + 1).split(",");
      for (int k = 0; k < 15; k++) {
        a[i * 15 + k] = Double.parseDouble(f[k]);
        b[i * 15 + k] = Double.parseDouble(f[15 + k]);
      }
    }
    double[] d = SatVector256.layout(a, b, n);
    boolean[] ref = new boolean[n];
    boolean[] out = new boolean[n];
    scalar(a, b, ref);
    SatVector256.kernel(d, out, n, a, b);
    int disagreements = 0;
    for (int i = 0; i < n; i++) {
      disagreements += out[i] != ref[i] ? 1 : 0;
    }
    System.out.println("pairs=" + n + " disagreements=" + disagreements);
    double[] s = new double[rounds];
    double[] v = new double[rounds];
    for (int r = 0; r < rounds; r++) {
      s[r] = time(() -> scalar(a, b, out), n);
      v[r] = time(() -> SatVector256.kernel(d, out, n, a, b), n);
      System.out.printf("round %d: scalar %.2f ns/pair  vector256 %.2f ns/pair%n", r, s[r], v[r]);
    }
    Arrays.sort(s);
    Arrays.sort(v);
    System.out.printf("median: scalar %.2f  vector256 %.2f%n", s[rounds / 2], v[rounds / 2]);
  }

  static void scalar(double[] a, double[] b, boolean[] out) {
    for (int i = 0; i < out.length; i++) {
      out[i] = SeparatingAxisTest.overlap(a, i, b, i);
    }
  }

  static double time(Runnable pass, int n) {
    for (int w = 0; w < 40; w++) {
      pass.run();
    }
    long[] ns = new long[21];
    for (int r = 0; r < ns.length; r++) {
      long t0 = System.nanoTime();
      pass.run();
      ns[r] = System.nanoTime() - t0;
    }
    Arrays.sort(ns);
    return (double) ns[ns.length / 2] / n;
  }
}
