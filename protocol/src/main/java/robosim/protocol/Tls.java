package robosim.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.util.Collections;
import java.util.List;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLEngine;
import javax.net.ssl.SSLSocket;
import javax.net.ssl.TrustManagerFactory;

/**
 * TLS 1.3 with the simulation's own key pair (JDK JSSE): one self-signed key pair per simulation, made
 * by {@code scripts/make-keys.sh} into a PKCS#12 file locked with the shared secret, and copied with
 * the secret to every machine of the simulation. Both ends present it and trust nothing else (mutual
 * TLS, the certificate pinned): a peer without the simulation's key pair never gets past TLS, so a
 * stranger beyond loopback never reaches the object streams, and a client knows it talks to the
 * simulation's Environment, not a relay. Host names are not checked: the pinned key pair is what
 * names the simulation, wherever it runs. Immutable; any thread.
 */
public final class Tls {
    /** The only protocol offered. */
    public static final String PROTOCOL = "TLSv1.3";
    /** The key pair's file in a keys directory. */
    public static final String KEY_STORE_FILE = "simulation.p12";

    private final SSLContext context;

    private Tls(SSLContext context) {
        this.context = context;
    }

    /**
     * Loads the key pair in {@code p12} (PKCS#12, locked with {@code password}); trusts its certificate only.
     *
     * @throws IOException naming the file and what is wrong with it
     */
    static Tls load(Path p12, char[] password) throws IOException {
        try (InputStream in = Files.newInputStream(p12)) {
            KeyStore store = KeyStore.getInstance("PKCS12");
            store.load(in, password);
            List<String> keys = Collections.list(store.aliases()).stream()
                    .filter(a -> isKey(store, a)).toList();
            if (keys.size() != 1) {
                throw new IOException(p12 + ": holds " + keys.size() + " key pairs, not the one scripts/make-keys.sh makes");
            }
            Certificate certificate = store.getCertificate(keys.get(0));
            KeyStore trusted = KeyStore.getInstance("PKCS12");
            trusted.load(null, null);
            trusted.setCertificateEntry("simulation", certificate);
            KeyManagerFactory km = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            km.init(store, password);
            TrustManagerFactory tm = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tm.init(trusted);
            SSLContext context = SSLContext.getInstance(PROTOCOL);
            context.init(km.getKeyManagers(), tm.getTrustManagers(), null);
            return new Tls(context);
        } catch (java.nio.file.NoSuchFileException e) {
            throw new IOException(p12 + ": no such file (scripts/make-keys.sh makes it)");
        } catch (java.nio.file.AccessDeniedException e) {
            throw new IOException(p12 + ": not readable by this user");
        } catch (GeneralSecurityException | IOException e) {
            if (e.getMessage() != null && e.getMessage().startsWith(p12.toString())) {
                throw (IOException) e;
            }
            throw new IOException(p12 + ": not a key store this secret opens (" + e.getMessage() + ")");
        }
    }

    private static boolean isKey(KeyStore store, String alias) {
        try {
            return store.isKeyEntry(alias);
        } catch (GeneralSecurityException e) {
            return false;
        }
    }

    /**
     * A server's engine for one connection (for Netty's {@code SslHandler} on the control port and the
     * remote-control link): TLS 1.3, the client must show the key pair.
     */
    public SSLEngine serverEngine() {
        SSLEngine e = context.createSSLEngine();
        e.setUseClientMode(false);
        e.setNeedClientAuth(true);
        e.setEnabledProtocols(new String[] {PROTOCOL});
        return e;
    }

    /**
     * The client's end of TLS over the connected {@code raw} socket, handshake done.
     *
     * @throws IOException naming the peer when the handshake fails
     */
    public SSLSocket client(Socket raw) throws IOException {
        SSLSocket s = (SSLSocket) context.getSocketFactory().createSocket(raw, raw.getInetAddress().getHostAddress(),
                raw.getPort(), true);
        s.setUseClientMode(true);
        return handshake(s, raw);
    }

    /**
     * The server's end of TLS over the accepted {@code raw} socket, whose first bytes ({@code greeting}) have been
     * read already, handshake done; the client must show the key pair.
     */
    public SSLSocket server(Socket raw, Greeting greeting) throws IOException {
        SSLSocket s = (SSLSocket) context.getSocketFactory().createSocket(raw, greeting.replay(), true);
        s.setUseClientMode(false);
        s.setNeedClientAuth(true);
        return handshake(s, raw);
    }

    private static SSLSocket handshake(SSLSocket s, Socket raw) throws IOException {
        s.setEnabledProtocols(new String[] {PROTOCOL});
        try {
            s.startHandshake();
            return s;
        } catch (IOException e) {
            raw.close();
            String why = String.valueOf(e.getMessage());
            boolean noTls = !(e instanceof javax.net.ssl.SSLHandshakeException) || why.contains("terminated the handshake");
            throw new ProtocolException("TLS handshake with " + raw.getInetAddress().getHostAddress() + ":"
                    + raw.getPort() + " failed: " + why + (noTls ? " (it may not speak TLS: an "
                    + "Environment's listening line says tls=on or tls=off)"
                    : " (does every process use the same ROBOSIM_KEYS?)"));
        }
    }

    @Override
    public String toString() {
        return "Tls[" + PROTOCOL + ", the simulation's key pair]";
    }
}
