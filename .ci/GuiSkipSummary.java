import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The build's closing note on render and window tests that skipped themselves outside CI (issue
 * 30): once, at the end of {@code ./mvnw -B verify}, how many were skipped and the one command that
 * installs what they need. Reads the counts the test JVM wrote (org.robotrun.GuiSkipCounter) and
 * removes the file; prints nothing when none was skipped or the tests did not run.
 * {@code java .ci/GuiSkipSummary.java target/gui-test-skips.txt}
 */
public class GuiSkipSummary {
  public static void main(String[] args) throws Exception {
    Path file = Path.of(args[0]);
    if (!Files.isRegularFile(file)) {
      return;
    }
    int render = 0;
    int window = 0;
    for (String line : Files.readAllLines(file)) {
      if (line.startsWith("render=")) {
        render = Integer.parseInt(line.substring(7).strip());
      } else if (line.startsWith("window=")) {
        window = Integer.parseInt(line.substring(7).strip());
      }
    }
    Files.delete(file);
    if (render + window == 0) {
      return;
    }
    boolean apt = Files.isExecutable(Path.of("/usr/bin/apt-get"));
    String install = apt
        ? "sudo apt-get install libosmesa6 libgl1-mesa-dri xvfb xauth xdotool"
        : "install Mesa (OSMesa), Xvfb, xauth and xdotool with your package manager";
    System.out.println("[WARNING] " + render + " render test(s) skipped (no headless OpenGL: Mesa) and " + window
        + " window test(s) skipped (no Xvfb, xauth or xdotool). To run them: " + install);
  }
}
