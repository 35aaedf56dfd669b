@echo off
rem Finds a Java 21 or newer for mvnw.cmd and robotrun.cmd (the Windows twin of find-jdk.sh) and
rem sets JAVA_HOME to it; exit code 1 and one line saying how to get one when there is none.
rem   call find-jdk.cmd javac   a JDK (java and javac), for building
rem   call find-jdk.cmd java    a runtime is enough
rem Order: JAVA_HOME; the java on the PATH; then the newest 21+ under %ProgramFiles%\Java,
rem Eclipse Adoptium, Microsoft, Zulu, Amazon Corretto, BellSoft, Semeru, %USERPROFILE%\.jdks,
rem %USERPROFILE%\.sdkman\candidates\java. The version comes from each JDK's "release" file.
set "RR_TOOL=%~1"
if "%RR_TOOL%"=="" set "RR_TOOL=javac"
set "RR_FOUND="
set "RR_BEST="
set "RR_BEST_M=0"
set "RR_OK="

if defined JAVA_HOME call :rr_check "%JAVA_HOME%"
if defined RR_OK set "RR_FOUND=%JAVA_HOME%"
if defined RR_FOUND goto rr_done

for /f "delims=" %%J in ('where java 2^>nul') do (
  if not defined RR_FOUND (
    call :rr_check "%%~dpJ.."
    if defined RR_OK for %%H in ("%%~dpJ..") do set "RR_FOUND=%%~fH"
  )
)
if defined RR_FOUND goto rr_done

for %%R in ("%ProgramFiles%\Java" "%ProgramFiles%\Eclipse Adoptium" "%ProgramFiles%\Microsoft" "%ProgramFiles%\Zulu" "%ProgramFiles%\Amazon Corretto" "%ProgramFiles%\BellSoft" "%ProgramFiles%\Semeru" "%USERPROFILE%\.jdks" "%USERPROFILE%\.sdkman\candidates\java") do (
  if exist "%%~R\" for /d %%H in ("%%~R\*") do call :rr_consider "%%~fH"
)
if defined RR_BEST set "RR_FOUND=%RR_BEST%"

:rr_done
set "RR_TOOL="
set "RR_OK="
set "RR_M="
set "RR_BEST="
set "RR_BEST_M="
if not defined RR_FOUND (
  echo RobotRun needs a JDK 21 or newer and found none ^(looked at JAVA_HOME, the PATH, %%ProgramFiles%%\Java and the other JDK folders, %%USERPROFILE%%\.jdks^); install one: winget install EclipseAdoptium.Temurin.21.JDK ^(or a JDK from adoptium.net^) 1>&2
  exit /b 1
)
set "JAVA_HOME=%RR_FOUND%"
set "RR_FOUND="
exit /b 0

:rr_consider
call :rr_check "%~1"
if not defined RR_OK goto :eof
if %RR_M% GTR %RR_BEST_M% (
  set "RR_BEST=%~1"
  set "RR_BEST_M=%RR_M%"
)
goto :eof

:rr_check
rem RR_OK=1 and RR_M=major when %1 is a Java 21+ home with bin\%RR_TOOL%.exe.
set "RR_OK="
set "RR_M=0"
if not exist "%~1\bin\%RR_TOOL%.exe" goto :eof
if not exist "%~1\release" goto :eof
for /f "tokens=2 delims==" %%V in ('findstr /b /c:"JAVA_VERSION=" "%~1\release"') do (
  for /f "tokens=1,2 delims=." %%A in (%%V) do (
    if "%%A"=="1" (set "RR_M=%%B") else (set "RR_M=%%A")
  )
)
if %RR_M% GEQ 21 set "RR_OK=1"
goto :eof
