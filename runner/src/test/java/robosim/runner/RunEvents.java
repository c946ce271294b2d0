package robosim.runner;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Departure;
import robosim.environment.run.RunListener;

/** Test fixture: what a run told its listener, with latches to wait on the first of each event. */
final class RunEvents implements RunListener {
    final CountDownLatch started = new CountDownLatch(1);
    final CountDownLatch geometryLost = new CountDownLatch(1);
    final CountDownLatch geometryAttached = new CountDownLatch(1);
    final CountDownLatch viewerDropped = new CountDownLatch(1);
    final CountDownLatch heldForViewer = new CountDownLatch(1);
    final List<String> droppedViewers = new CopyOnWriteArrayList<>();
    final CountDownLatch robotLeft = new CountDownLatch(1);
    final List<Departure> departures = new CopyOnWriteArrayList<>();
    /** The names of the threads the listener was called on. */
    final List<String> threads = new CopyOnWriteArrayList<>();

    @Override
    public void started(int robots) {
        threads.add(Thread.currentThread().getName());
        started.countDown();
    }

    @Override
    public void robotLeft(Departure departure) {
        threads.add(Thread.currentThread().getName());
        departures.add(departure);
        robotLeft.countDown();
    }

    @Override
    public void geometryLost(long step) {
        threads.add(Thread.currentThread().getName());
        geometryLost.countDown();
    }

    @Override
    public void geometryAttached(long step) {
        threads.add(Thread.currentThread().getName());
        geometryAttached.countDown();
    }

    @Override
    public void heldForViewer(long step) {
        threads.add(Thread.currentThread().getName());
        heldForViewer.countDown();
    }

    @Override
    public void viewerDropped(String viewer, String why) {
        threads.add(Thread.currentThread().getName());
        droppedViewers.add(viewer + ": " + why);
        viewerDropped.countDown();
    }
}
