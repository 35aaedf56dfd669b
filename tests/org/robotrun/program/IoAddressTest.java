package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The one reader of KIND[i] addresses (wiring, production setup, key scripts). */
class IoAddressTest {
  @Test
  void readsKindAndIndexInAnyCaseWithSpacesInsideTheBrackets() {
    assertThat(IoAddress.parse("DO[3]")).contains(new IoAddress("DO", 3));
    assertThat(IoAddress.parse(" ui[ 6 ] ")).contains(new IoAddress("UI", 6));
    assertThat(IoAddress.parse("F[123456789]")).contains(new IoAddress("F", 123456789));
    assertThat(IoAddress.parse("DO[1234567890]")).isEmpty();
    assertThat(IoAddress.parse("DO3")).isEmpty();
    assertThat(IoAddress.parse("DO[-1]")).isEmpty();
    assertThat(IoAddress.parse("D O[1]")).isEmpty();
    assertThat(IoAddress.parse("DO[1] ON")).isEmpty();
  }

  @Test
  void onARobotTheRobotIsEverythingBeforeTheLastDotAheadOfTheAddress() {
    assertThat(IoAddress.parseOnRobot("robot1.DO[10]"))
        .contains(new IoAddress.Located("robot1", new IoAddress("DO", 10)));
    assertThat(IoAddress.parseOnRobot("cell.arm 2.di[ 4 ]"))
        .contains(new IoAddress.Located("cell.arm 2", new IoAddress("DI", 4)));
    assertThat(IoAddress.parseOnRobot("DO[1]")).isEqualTo(Optional.empty());
    assertThat(IoAddress.parseOnRobot(".DO[1]")).isEmpty();
    assertThat(IoAddress.parseOnRobot("robot1. DO[1]")).isEmpty();
  }
}
