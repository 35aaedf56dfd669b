@echo off
rem Starts RobotRun on Windows. Builds target\robotrun.jar on first use. Needs a JDK 21+, found as
rem mvnw.cmd finds it (.mvn\find-jdk.cmd: JAVA_HOME, the PATH, %ProgramFiles%\Java and the other JDK folders).
setlocal
set HERE=%~dp0
call "%HERE%.mvn\find-jdk.cmd" java || exit /b 2
set JAVA="%JAVA_HOME%\bin\java"
if not exist "%HERE%target\robotrun.jar" (
  echo robotrun: building on first use... 1>&2
  pushd "%HERE%"
  call mvnw.cmd -q -B -DskipTests package || (popd & exit /b 1)
  popd
)
%JAVA% --enable-native-access=ALL-UNNAMED %ROBOTRUN_JAVA_OPTS% -jar "%HERE%target\robotrun.jar" %*
