package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_A;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F3;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;
import static org.lwjgl.glfw.GLFW.GLFW_PRESS;
import static org.lwjgl.glfw.GLFW.GLFW_RELEASE;
import static org.lwjgl.glfw.GLFW.GLFW_REPEAT;

import org.junit.jupiter.api.Test;

/**
 * Issue 26: typing a space into the Hand in dialog while the DEADMAN was held released it (the
 * press went to the text field, its release to the pendant).
 */
class TypingKeyFilterTest {
  @Test
  void aSpaceTypedIntoAFieldWhileTheDeadmanIsHeldWithSpaceNeverReachesThePendant() {
    TypingKeyFilter f = new TypingKeyFilter();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_PRESS, false)).isTrue();   // DEADMAN held with Space
    // the Hand in dialog's name field has the keyboard; a space is typed (a synthetic press, xdotool)
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_PRESS, true)).isFalse();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_RELEASE, true)).isFalse();
    assertThat(f.pass(GLFW_KEY_A, GLFW_PRESS, true)).isFalse();
    assertThat(f.pass(GLFW_KEY_A, GLFW_REPEAT, true)).isFalse();
    assertThat(f.pass(GLFW_KEY_A, GLFW_RELEASE, true)).isFalse();
    // Space really let go: the pendant hears it
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_RELEASE, true)).isTrue();
  }

  @Test
  void aKeyHeldBeforeTheFieldTookTheKeyboardStillStopsWhenLetGo() {
    TypingKeyFilter f = new TypingKeyFilter();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_PRESS, false)).isTrue();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_RELEASE, true)).isTrue();
  }

  @Test
  void aKeyTypedIntoTheFieldAndLetGoAfterTheFieldClosedIsStillTheFields() {
    TypingKeyFilter f = new TypingKeyFilter();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_PRESS, true)).isFalse();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_RELEASE, false)).isFalse();
    // and the next press outside a field is the pendant's again
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_PRESS, false)).isTrue();
    assertThat(f.pass(GLFW_KEY_SPACE, GLFW_RELEASE, false)).isTrue();
  }

  @Test
  void functionKeysReachThePendantWhileTyping() {
    TypingKeyFilter f = new TypingKeyFilter();
    assertThat(f.pass(GLFW_KEY_F3, GLFW_PRESS, true)).isTrue();
    assertThat(f.pass(GLFW_KEY_F3, GLFW_RELEASE, true)).isTrue();
  }
}
