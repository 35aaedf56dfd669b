package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class InputEdgesTest {
  private final InputEdges edges = new InputEdges();

  private List<String> frame() {
    List<String> seen = new ArrayList<>();
    edges.apply((id, down) -> seen.add(id + (down ? " down" : " up")));
    return seen;
  }

  @Test
  void aPressAndReleaseWithinOneFrameShowAsOneFrameDownThenOneFrameUp() {
    edges.record(0, true);
    edges.record(0, false);
    assertThat(frame()).containsExactly("0 down");
    assertThat(frame()).containsExactly("0 up");
    assertThat(frame()).isEmpty();
    assertThat(edges.isEmpty()).isTrue();
  }

  @Test
  void twoTapsInOneFrameAreTwoClicksOverFourFrames() {
    edges.record(1, true);
    edges.record(1, false);
    edges.record(1, true);
    edges.record(1, false);
    List<String> all = new ArrayList<>();
    for (int i = 0; i < 5; i++) {
      all.addAll(frame());
    }
    assertThat(all).containsExactly("1 down", "1 up", "1 down", "1 up");
  }

  @Test
  void buttonsAreQueuedSeparatelyAndRepeatsOfTheSameStateAreDropped() {
    edges.record(0, true);
    edges.record(0, true);  // a repeat
    edges.record(1, true);
    assertThat(frame()).containsExactly("0 down", "1 down");
    edges.record(0, true);  // still down: nothing new
    assertThat(frame()).isEmpty();
  }

  @Test
  void applyReportsWhenMoreEdgesWait() {
    edges.record(0, true);
    edges.record(0, false);
    assertThat(edges.apply((id, d) -> { })).isTrue();
    assertThat(edges.apply((id, d) -> { })).isFalse();
  }
}
