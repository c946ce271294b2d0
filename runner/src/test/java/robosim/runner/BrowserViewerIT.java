package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.support.ui.WebDriverWait;
import robosim.control.ControlClient;
import robosim.protocol.PoseUpdate;
import robosim.protocol.WorldSnapshot;
import robosim.web.WebViewerServer;

/**
 * The browser viewer in a real headless browser (Debian's chromium and chromedriver, which {@code .ci/run}
 * installs; nothing is downloaded): the page connects to a running 10-robot simulation, its step
 * advances, and, the run paused, every robot is drawn where the run put it (the robot table says the
 * same poses), the watch panel shows the robot's sonar and no bump sensor, which it does not have, and the 3D
 * view renders the robots, the arena's walls, each robot's name and, while the trails box is checked, their
 * trails. The run goes on until the test stops it. On a replay of a recorded run, a seek starts the picture
 * afresh at the sought step: no trail across the jump, the robots where that step has them, the steps per
 * second measured anew. What a world's loop functions draw shows in both views.
 */
class BrowserViewerIT {
    private static final Path CHROMIUM = Path.of("/usr/bin/chromium");
    private static final Path CHROMEDRIVER = Path.of("/usr/bin/chromedriver");
    private static final long LONG_S = 120;
    /** The replayed recording's steps: a seek forward, a seek back and a seek forward while running fit in it. */
    private static final int RECORDED_STEPS = 300;
    /** The 2D view's robot colour (#2a62c9), as drawn. */
    private static final int[] ROBOT = {0x2a, 0x62, 0xc9};
    /** The one browser of the tests here (its start is much of a test's time on a loaded machine). */
    private static WebDriver page;

    @BeforeAll
    static void startTheBrowser() {
        Assumptions.assumeTrue(Files.isExecutable(CHROMIUM) && Files.isExecutable(CHROMEDRIVER),
                "needs Debian's chromium and chromium-driver (.ci/run installs them)");
        page = browser();
    }

    @AfterAll
    static void quitTheBrowser() {
        if (page != null) {
            page.quit();
        }
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.MINUTES)
    void thePageShowsTheRunIn2DAnd3D() throws Exception {
        Map<Long, PoseUpdate> seen = new ConcurrentHashMap<>();
        CountDownLatch pageHasTheWorld = new CountDownLatch(1);
        Object[] shown = new Object[4]; // the paused step, the table's rows, the pixels at each robot, the robot panel
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"));
        sim.settings(s -> s.speed(40)) // (80 steps a second: a page can watch it go)
                .onUpdate((u, port) -> seen.put(u.step(), u))
                .sideline((env, ports) -> {
                    try (WebViewerServer web = new WebViewerServer("127.0.0.1", ports[1], null,
                            (verb, arg) -> "{\"ok\":true}")) {
                        web.start(java.net.InetAddress.getLoopbackAddress(), 0);
                        try {
                            String watched = sim.spec.robots().get(0).name();
                            page.get("http://localhost:" + web.port() + "/?watch=" + watched);
                            WebDriverWait wait = new WebDriverWait(page, Duration.ofSeconds(LONG_S));
                            wait.until(p -> p.findElements(By.cssSelector("#robots tbody tr")).size() == 10);
                            pageHasTheWorld.countDown(); // the robots start now
                            long first = wait.until(p -> stepShown(p) >= 0 ? stepShown(p) : null);
                            // the step advances, and the trails grow: the page gets at most 10 updates a second, a
                            // point of each robot's trail each, so some 200 steps (2.5 s at 80 steps a second) before
                            // the pause, for trails the 3D view's check below can see go (20 steps left a few points)
                            wait.until(p -> stepShown(p) > first && stepShown(p) >= 200);
                            env.pause(LONG_S, TimeUnit.SECONDS);
                            long last = env.status().step() - 1; // (the wire's step: the page shows it as last + 1)
                            PoseUpdate expected = wait.until(p -> seen.get(last));
                            wait.until(p -> stepShown(p) == last + 1 && page.findElement(By.id("state")).getText()
                                    .equals("PAUSED") && tableShows(p, expected));
                            shown[0] = last;
                            shown[1] = page.findElements(By.cssSelector("#robots tbody tr")).stream()
                                    .map(r -> r.getText()).toList();
                            shown[2] = robotPixels(page, wait.until(p -> sim.snapshot), expected);
                            String command = "command (step " + (last + 1) + "): move ";
                            shown[3] = wait.until(p -> { // (the robot panel: the watched robot's last step)
                                String facts = p.findElement(By.id("facts")).getText();
                                return facts.contains(command) ? facts : null;
                            });
                            assertFalse(page.findElement(By.id("bump")).isDisplayed(),
                                    "no bump row: " + watched + " has no bump sensor");
                            String log = page.findElement(By.id("log")).getText();
                            assertTrue(log.replaceAll("\\s+", " ").contains(" in from "),
                                    "its inbox in the panel's log: " + log);
                            assertTrue(polarCentreIsTheRobot(page), "the polar plot has the robot at its centre");
                            page.findElement(By.cssSelector("input[name=view][value='3d']")).click();
                            long blue = wait.until(p -> {
                                long n = bluePixels3d(p);
                                return n > 50 ? n : null;
                            });
                            assertTrue(blue > 50, "the 3D view draws the robots: " + blue + " robot-blue pixels");
                            List<String> names = sim.spec.robots().stream().map(r -> r.name()).toList();
                            assertEquals(names, wait.until(p -> labels3d(p).size() == names.size() ? labels3d(p) : null),
                                    "the 3D view names each robot, in the view");
                            long walls = wallPixels3d(page);
                            assertTrue(walls > 2000, "the 3D view draws the arena's walls: " + walls + " wall-grey pixels");
                            long trails = trailPixels3d(page);
                            page.findElement(By.id("trails")).click(); // (the run is paused: only the trails can go)
                            wait.until(p -> trailPixels3d(p) < trails - 100); // the 3D view drew them
                        } finally {
                            env.stop("the test has seen what it needed"); // (whatever happened above)
                        }
                    }
                }).run(1_000_000, true, () -> robot -> { // (until the test stops it)
                    pageHasTheWorld.await(LONG_S, TimeUnit.SECONDS);
                    new Chatter().run(robot);
                });
        assertTrue(shown[0] != null, "the page was checked: " + sim.summary.reason());
        long step = (Long) shown[0];
        PoseUpdate u = sim.updates.get((int) step);
        @SuppressWarnings("unchecked")
        List<String> rows = (List<String>) shown[1];
        for (int i = 0; i < u.count(); i++) {
            String[] cells = rows.get(i).split("\\s+");
            assertEquals(sim.spec.robots().get(i).name(), cells[0]);
            assertEquals(u.xMm(i) / 1000, Double.parseDouble(cells[1]), 0.0006, "x of " + cells[0]);
            assertEquals(u.yMm(i) / 1000, Double.parseDouble(cells[2]), 0.0006, "y of " + cells[0]);
        }
        @SuppressWarnings("unchecked")
        List<Boolean> drawn = (List<Boolean>) shown[2];
        for (int i = 0; i < drawn.size(); i++) {
            assertTrue(drawn.get(i), "robot " + i + " is drawn where the run put it at step " + step);
        }
        robosim.protocol.RobotView v = sim.views.get((int) step); // (robot 0's, as the run's own viewer got it)
        String facts = (String) shown[3];
        assertTrue(facts.startsWith(sim.spec.robots().get(0).name() + " ("), facts);
        assertTrue(facts.contains("\n  sonar "), "its sonar (an ArRobot has sonars): " + facts);
        assertTrue(facts.contains(String.format(java.util.Locale.ROOT, "command (step %d): move %.1f mm, turn %.1f deg",
                step + 1, v.moveMm(), v.turnDeg())), "the panel shows the robot's own command: " + facts);
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.MINUTES)
    void aSeekStartsThePictureAfreshAtTheSoughtStep(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("run.rec");
        InJvmSimulation live = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .settings(s -> s.record(file)).run(RECORDED_STEPS, true, Chatter::new);
        assertTrue(live.summary.completed(), live.summary.reason());
        try (ProcessLines replay = ReplayTest.replay(file, "--paused", "--web-port", "0");
                ControlClient control = new ControlClient("127.0.0.1", ReplayTest.port(replay, "control"), null,
                        (int) (LONG_S * 1000))) {
            page.get("http://localhost:" + ReplayTest.port(replay, "web") + "/");
            WebDriverWait wait = new WebDriverWait(page, Duration.ofSeconds(LONG_S));
            wait.until(p -> p.findElements(By.cssSelector("#robots tbody tr")).size() == 10);
            ok(control, "speed 10"); // (20 steps a second: the page, 10 updates a second, draws trails)
            ok(control, "resume");
            wait.until(p -> stepShown(p) >= 30);
            long paused = stepOf(ok(control, "pause"));
            shows(wait, live, paused);
            assertTrue(trailPixels(page, live, paused) > 0, "the trails drawn so far");
            ok(control, "speed 20"); // (not one of the list's own speeds: the page adds it, and shows it)
            wait.until(p -> "20".equals(p.findElement(By.id("speed")).getDomProperty("value")));
            wait.until(p -> p.findElement(By.id("at")).getText().equals(stepShown(p) + " / " + RECORDED_STEPS)
                    && p.findElement(By.id("timeline")).getDomProperty("value").equals(Long.toString(stepShown(p))));

            long forward = seekForward(live, paused);
            ok(control, "seek " + forward);
            shows(wait, live, forward);
            assertEquals(0, trailPixels(page, live, forward), "no trail across a seek forward");
            assertEquals(List.of(), notDrawn(page, live, forward), "robots not where step " + forward + " has them");
            long back = paused / 2;
            ok(control, "seek " + back);
            shows(wait, live, back);
            assertEquals(0, trailPixels(page, live, back), "no trail across a seek back");

            ((JavascriptExecutor) page).executeScript(RATES_SHOWN);
            ok(control, "speed 2"); // (4 steps a second)
            ok(control, "resume");
            wait.until(p -> !rates(p, 0).isEmpty()); // (measured once: a seek comes in a measure under way)
            long jump = back + Math.min(150, (RECORDED_STEPS - back) / 2);
            ok(control, "seek " + jump);
            wait.until(p -> stepShown(p) >= jump + 6); // (1.5 s on: the page has measured since the seek)
            List<Double> after = wait.until(p -> rates(p, jump).isEmpty() ? null : rates(p, jump)); // (one at least)
            assertTrue(after.stream().allMatch(r -> r < 20), "steps per second after a seek forward by "
                    + (jump - back) + " steps while running at 4 steps a second: " + after);
            ok(control, "stop");
            assertEquals(0, replay.exit(LONG_S), replay.output());
        }
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.MINUTES)
    void theLoopFunctionsDrawingShowsIn2DAnd3D(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("square.xml");
        Files.writeString(file, """
                <environment name="square" timeStepMs="100">
                  <loopFunctions class="robosim.runner.DrawsASquare"/>
                  <arena width="5" height="5"/>
                  <robots><robot name="r1" type="ArRobot" x="0.5" y="0.5" heading="0"/></robots>
                </environment>
                """);
        long[] magenta = new long[2]; // the 2D view's pixels of the square's colour, the 3D view's
        InJvmSimulation sim = new InJvmSimulation(file);
        sim.settings(s -> s.speed(10)).sideline((env, ports) -> {
            try (WebViewerServer web = new WebViewerServer("127.0.0.1", ports[1], null, (verb, arg) -> "{\"ok\":true}")) {
                web.start(java.net.InetAddress.getLoopbackAddress(), 0);
                try {
                    page.get("http://localhost:" + web.port() + "/");
                    WebDriverWait wait = new WebDriverWait(page, Duration.ofSeconds(LONG_S));
                    wait.until(p -> stepShown(p) >= 1); // (the drawing comes with step 0's update)
                    magenta[0] = wait.until(p -> magentaPixels2d(p) > 500 ? magentaPixels2d(p) : null);
                    page.findElement(By.cssSelector("input[name=view][value='3d']")).click();
                    magenta[1] = wait.until(p -> pixels3d(p, MAGENTA) > 100 ? pixels3d(p, MAGENTA) : null);
                } finally {
                    page.findElement(By.cssSelector("input[name=view][value='2d']")).click(); // (as the others expect)
                    env.stop("the test has seen what it needed");
                }
            }
        }).run(1_000_000, true, () -> robot -> {
            while (true) {
                robot.sleep(100);
            }
        });
        assertTrue(magenta[0] > 500, "the 2D view draws the square: " + magenta[0] + " magenta pixels");
        assertTrue(magenta[1] > 100, "the 3D view draws the square: " + magenta[1] + " magenta pixels");
    }

    /** The square's colour, strongly: red and blue high, green well under both. */
    private static final String MAGENTA = "r > 150 && b > 150 && g < Math.min(r, b) - 80";

    /** Pixels of the 2D view's canvas in the square's colour. */
    private static long magentaPixels2d(WebDriver page) {
        Object n = ((JavascriptExecutor) page).executeScript("const c = document.getElementById('view2d');"
                + "const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;"
                + "for (let i = 0; i < d.length; i += 4) { const r = d[i], g = d[i + 1], b = d[i + 2]; if (" + MAGENTA
                + ") n++; }"
                + "return n;");
        return ((Number) n).longValue();
    }

    /**
     * Waits until the page shows step {@code step} (as displays number steps: the world after that many, the update
     * of wire step {@code step - 1}): its number, its poses in the table, PAUSED.
     */
    private static void shows(WebDriverWait wait, InJvmSimulation live, long step) {
        wait.until(p -> stepShown(p) == step && tableShows(p, live.updates.get((int) step - 1))
                && p.findElement(By.id("state")).getText().equals("PAUSED"));
    }

    /**
     * A step well ahead of {@code from} where robot 0 stands away from where it stood then (its lane's length is 10 m);
     * steps as displays number them.
     */
    private static long seekForward(InJvmSimulation live, long from) {
        PoseUpdate a = live.updates.get((int) from - 1);
        for (long k = from + 20; k < RECORDED_STEPS; k++) {
            PoseUpdate b = live.updates.get((int) k - 1);
            if (Math.hypot(b.xMm(0) - a.xMm(0), b.yMm(0) - a.yMm(0)) > 2000) {
                return k;
            }
        }
        throw new AssertionError("robot 0 never left the place it had at step " + from);
    }

    private static JsonNode ok(ControlClient control, String request) throws java.io.IOException {
        JsonNode reply = control.request(request);
        assertTrue(reply.path("ok").asBoolean(), request + ": " + reply);
        return reply;
    }

    private static long stepOf(JsonNode pauseReply) {
        String message = pauseReply.path("message").asText(); // "paused at step N"
        return Long.parseLong(message.substring(message.lastIndexOf(' ') + 1));
    }

    /** Records each steps-per-second figure the page shows, with the step it shows beside it (the same frame). */
    private static final String RATES_SHOWN = "window.ratesShown = [];"
            + "new MutationObserver(() => window.ratesShown.push([Number(document.getElementById('step').textContent),"
            + " Number(document.getElementById('rate').textContent)]))"
            + ".observe(document.getElementById('rate'), {childList: true, characterData: true, subtree: true});";

    /** The steps-per-second figures above 0 the page has shown beside a step from {@code step} on. */
    private static List<Double> rates(WebDriver page, long step) {
        @SuppressWarnings("unchecked")
        List<Number> shown = (List<Number>) ((JavascriptExecutor) page).executeScript(
                "return window.ratesShown.filter(([s, r]) => s >= arguments[0] && r > 0).map(([s, r]) => r);", step);
        return shown.stream().map(Number::doubleValue).toList();
    }

    /**
     * Trail-blue pixels of the 2D view away from the robots (their discs and 3 px around) at the poses of
     * {@code step} (as displays number it), by the page's own fit of the arena: what its trails draw (nothing else
     * there is blue).
     */
    private static long trailPixels(WebDriver page, InJvmSimulation live, long step) {
        View2d v = View2d.of(page, live.snapshot);
        PoseUpdate u = live.updates.get((int) step - 1);
        List<List<Double>> centres = new java.util.ArrayList<>();
        double radius = 0;
        for (int i = 0; i < u.count(); i++) {
            centres.add(List.of(v.x(u.xMm(i)), v.y(u.yMm(i))));
            radius = Math.max(radius, live.snapshot.radiusMm(i) * v.scale() + 3);
        }
        Object n = ((JavascriptExecutor) page).executeScript("const c = document.getElementById('view2d');"
                + "const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
                + "const centres = arguments[0], r = arguments[1]; let n = 0;"
                + "for (let i = 0; i < d.length; i += 4) {"
                + "  if (!(d[i + 2] > d[i] + 20 && d[i + 2] > d[i + 1] + 10)) continue;"
                + "  const x = (i / 4) % c.width, y = Math.floor(i / 4 / c.width);"
                + "  if (!centres.some(([cx, cy]) => (x - cx) ** 2 + (y - cy) ** 2 <= r * r)) n++;"
                + "}"
                + "return n;", centres, radius);
        return ((Number) n).longValue();
    }

    /** The robots (indexes) the 2D view does not draw at their poses of {@code step} (as displays number it). */
    private static List<Integer> notDrawn(WebDriver page, InJvmSimulation live, long step) {
        List<Boolean> drawn = robotPixels(page, live.snapshot, live.updates.get((int) step - 1));
        return java.util.stream.IntStream.range(0, drawn.size()).filter(i -> !drawn.get(i)).boxed().toList();
    }

    /** The pixel at the centre of the robot panel's polar plot is the page's robot blue. */
    private static boolean polarCentreIsTheRobot(WebDriver page) {
        @SuppressWarnings("unchecked")
        List<Number> rgb = (List<Number>) ((JavascriptExecutor) page).executeScript(
                "const c = document.getElementById('polar'); const x = Math.floor(c.width / 2) + 1;"
                        + "return Array.from(c.getContext('2d').getImageData(x, x + 1, 1, 1).data.slice(0, 3));");
        return Math.abs(rgb.get(0).intValue() - 0x2a) <= 12 && Math.abs(rgb.get(1).intValue() - 0x62) <= 12
                && Math.abs(rgb.get(2).intValue() - 0xc9) <= 12;
    }

    private static WebDriver browser() {
        ChromeOptions options = new ChromeOptions();
        options.setBinary(CHROMIUM.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,800",
                "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--disable-gpu-sandbox");
        ChromeDriverService service = new ChromeDriverService.Builder().usingDriverExecutable(CHROMEDRIVER.toFile())
                .usingAnyFreePort().build();
        return new ChromeDriver(service, options);
    }

    /** True once the page's robot table shows the poses of {@code u} (it is redrawn a few times a second). */
    private static boolean tableShows(WebDriver page, PoseUpdate u) {
        List<String> rows = page.findElements(By.cssSelector("#robots tbody tr")).stream().map(r -> r.getText()).toList();
        for (int i = 0; i < u.count(); i++) {
            String[] cells = rows.get(i).split("\\s+");
            if (cells.length < 3 || Math.abs(Double.parseDouble(cells[1]) - u.xMm(i) / 1000) > 0.0006
                    || Math.abs(Double.parseDouble(cells[2]) - u.yMm(i) / 1000) > 0.0006) {
                return false;
            }
        }
        return true;
    }

    private static long stepShown(WebDriver page) {
        String s = page.findElement(By.id("step")).getText();
        return s.matches("\\d+") ? Long.parseLong(s) : -1;
    }

    /**
     * For each robot: whether the 2D view has it at the run's pose of {@code step}, by the page's own fit
     * of the arena (no zoom or pan was made): at least two of four points half a radius from its centre
     * are robot-blue (its heading line, a trail or a neighbour's name may cover one).
     */
    private static List<Boolean> robotPixels(WebDriver page, WorldSnapshot world, PoseUpdate u) {
        JavascriptExecutor js = (JavascriptExecutor) page;
        View2d v = View2d.of(page, world);
        List<Boolean> drawn = new java.util.ArrayList<>();
        for (int i = 0; i < u.count(); i++) {
            double radiusPx = world.radiusMm(i) * v.scale();
            double x = v.x(u.xMm(i));
            double y = v.y(u.yMm(i));
            int blue = 0;
            for (double[] d : new double[][] {{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                @SuppressWarnings("unchecked")
                List<Number> rgb = (List<Number>) js.executeScript("const d = document.getElementById('view2d')"
                        + ".getContext('2d').getImageData(arguments[0], arguments[1], 1, 1).data; return [d[0], d[1], d[2]];",
                        (int) Math.round(x + d[0] * radiusPx / 2), (int) Math.round(y + d[1] * radiusPx / 2));
                boolean robot = true;
                for (int c = 0; c < 3; c++) {
                    robot &= Math.abs(rgb.get(c).intValue() - ROBOT[c]) <= 12;
                }
                blue += robot ? 1 : 0;
            }
            drawn.add(blue >= 2);
        }
        return drawn;
    }

    /** The 2D view's fit of the arena (no zoom or pan made): world mm to canvas px, as the page computes it. */
    private record View2d(double scale, double offX, double offY, double height) {
        static View2d of(WebDriver page, WorldSnapshot world) {
            @SuppressWarnings("unchecked")
            Map<String, Object> size = (Map<String, Object>) ((JavascriptExecutor) page).executeScript(
                    "const c = document.getElementById('view2d'); return {w: c.width, h: c.height};");
            double w = ((Number) size.get("w")).doubleValue();
            double h = ((Number) size.get("h")).doubleValue();
            robosim.protocol.Arena a = world.arena();
            double aw = a.maxXMm() - a.minXMm();
            double ah = a.maxYMm() - a.minYMm();
            double scale = 0.95 * Math.min(w / aw, h / ah);
            return new View2d(scale, (w - aw * scale) / 2 - a.minXMm() * scale, (h - ah * scale) / 2 - a.minYMm() * scale, h);
        }

        double x(double xMm) {
            return xMm * scale + offX;
        }

        double y(double yMm) {
            return height - (yMm * scale + offY);
        }
    }

    /** The names over the 3D view, in robot order, of the labels shown whole inside it. */
    private static List<String> labels3d(WebDriver page) {
        @SuppressWarnings("unchecked")
        List<String> shown = (List<String>) ((JavascriptExecutor) page).executeScript(
                "const v = document.getElementById('view3d').getBoundingClientRect();"
                + "return [...document.querySelectorAll('#view3d .label')].filter((l) => { const r = l.getBoundingClientRect();"
                + "  return !l.hidden && r.width > 0 && r.left >= v.left && r.right <= v.right && r.top >= v.top"
                + "    && r.bottom <= v.bottom; }).map((l) => l.textContent);");
        return shown;
    }

    /** Wall-grey pixels in the 3D view's canvas: grey, darker than the floor, lighter than the robots' noses. */
    private static long wallPixels3d(WebDriver page) {
        return pixels3d(page, "Math.max(r, g, b) - Math.min(r, g, b) <= 6 && r >= 0x38 && r <= 0xb0");
    }

    /** Trail-blue pixels in the 3D view's canvas (and robots' edges: bluer than the floor, less than a robot). */
    private static long trailPixels3d(WebDriver page) {
        return pixels3d(page, "b > r + 20 && b > g + 10 && !(b > r + 60 && b > g + 30)");
    }

    /** Pixels of the 3D view's canvas (copied into a 2D canvas to read them) for which {@code test} of r, g, b holds. */
    private static long pixels3d(WebDriver page, String test) {
        Object n = ((JavascriptExecutor) page).executeScript("const g = document.querySelector('#view3d canvas');"
                + "if (!g || g.width === 0) return 0; const c = document.createElement('canvas');"
                + "c.width = g.width; c.height = g.height; const x = c.getContext('2d'); x.drawImage(g, 0, 0);"
                + "const d = x.getImageData(0, 0, c.width, c.height).data; let n = 0;"
                + "for (let i = 0; i < d.length; i += 4) { const r = d[i], g = d[i + 1], b = d[i + 2]; if (" + test + ") n++; }"
                + "return n;");
        return ((Number) n).longValue();
    }

    /** Robot-blue pixels in the 3D view's canvas (copied into a 2D canvas to read them). */
    private static long bluePixels3d(WebDriver page) {
        Object n = ((JavascriptExecutor) page).executeScript("const g = document.querySelector('#view3d canvas');"
                + "if (!g || g.width === 0) return 0; const c = document.createElement('canvas');"
                + "c.width = g.width; c.height = g.height; const x = c.getContext('2d'); x.drawImage(g, 0, 0);"
                + "const d = x.getImageData(0, 0, c.width, c.height).data; let n = 0;"
                + "for (let i = 0; i < d.length; i += 4) { if (d[i + 2] > d[i] + 60 && d[i + 2] > d[i + 1] + 30) n++; }"
                + "return n;");
        return ((Number) n).longValue();
    }
}
