package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.support.ui.WebDriverWait;
import robosim.protocol.PoseUpdate;
import robosim.protocol.WorldSnapshot;
import robosim.web.WebViewerServer;

/**
 * The browser viewer in a real headless browser (Debian's chromium and chromedriver, which {@code .ci/run}
 * installs; nothing is downloaded): the page connects to a running 10-robot simulation, its step
 * advances, and, the run paused, every robot is drawn where the run put it (the robot table says the
 * same poses) and the 3D view renders the robots. The run goes on until the test stops it.
 */
class BrowserViewerIT {
    private static final Path CHROMIUM = Path.of("/usr/bin/chromium");
    private static final Path CHROMEDRIVER = Path.of("/usr/bin/chromedriver");
    private static final long LONG_S = 120;
    /** The 2D view's robot colour (#2a62c9), as drawn. */
    private static final int[] ROBOT = {0x2a, 0x62, 0xc9};

    @Test
    @Timeout(value = 10, unit = TimeUnit.MINUTES)
    void thePageShowsTheRunIn2DAnd3D() throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(CHROMIUM) && Files.isExecutable(CHROMEDRIVER),
                "needs Debian's chromium and chromium-driver (.ci/run installs them)");
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
                        WebDriver page = browser();
                        try {
                            String watched = sim.spec.robots().get(0).name();
                            page.get("http://localhost:" + web.port() + "/?watch=" + watched);
                            WebDriverWait wait = new WebDriverWait(page, Duration.ofSeconds(LONG_S));
                            wait.until(p -> p.findElements(By.cssSelector("#robots tbody tr")).size() == 10);
                            pageHasTheWorld.countDown(); // the robots start now
                            long first = wait.until(p -> stepShown(p) >= 0 ? stepShown(p) : null);
                            wait.until(p -> stepShown(p) > first); // the step advances
                            env.pause(LONG_S, TimeUnit.SECONDS);
                            long last = env.status().step() - 1;
                            PoseUpdate expected = wait.until(p -> seen.get(last));
                            wait.until(p -> stepShown(p) == last && page.findElement(By.id("state")).getText()
                                    .equals("PAUSED") && tableShows(p, expected));
                            shown[0] = last;
                            shown[1] = page.findElements(By.cssSelector("#robots tbody tr")).stream()
                                    .map(r -> r.getText()).toList();
                            shown[2] = robotPixels(page, wait.until(p -> sim.snapshot), expected);
                            String command = "command (step " + last + "): move ";
                            shown[3] = wait.until(p -> { // (the robot panel: the watched robot's last step)
                                String facts = p.findElement(By.id("facts")).getText();
                                return facts.contains(command) ? facts : null;
                            });
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
                        } finally {
                            page.quit();
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
        assertTrue(facts.contains(String.format(java.util.Locale.ROOT, "command (step %d): move %.1f mm, turn %.1f deg",
                step, v.moveMm(), v.turnDeg())), "the panel shows the robot's own command: " + facts);
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
        @SuppressWarnings("unchecked")
        Map<String, Object> fit = (Map<String, Object>) js.executeScript("const c = document.getElementById('view2d');"
                + "return {w: c.width, h: c.height};");
        double w = ((Number) fit.get("w")).doubleValue();
        double h = ((Number) fit.get("h")).doubleValue();
        robosim.protocol.Arena a = world.arena();
        double aw = a.maxXMm() - a.minXMm();
        double ah = a.maxYMm() - a.minYMm();
        double scale = 0.95 * Math.min(w / aw, h / ah);
        double offX = (w - aw * scale) / 2 - a.minXMm() * scale;
        double offY = (h - ah * scale) / 2 - a.minYMm() * scale;
        List<Boolean> drawn = new java.util.ArrayList<>();
        for (int i = 0; i < u.count(); i++) {
            double radiusPx = world.radiusMm(i) * scale;
            double x = u.xMm(i) * scale + offX;
            double y = h - (u.yMm(i) * scale + offY);
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
