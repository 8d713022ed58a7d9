package ray.viewer;

import java.util.Locale;
import javax.swing.UIManager;
import javax.swing.UnsupportedLookAndFeelException;
import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLightLaf;

/**
 * Chooses the viewer's look and feel: FlatLaf's light theme by default; the system property
 * {@code raytracer.laf} or the environment variable {@code RAYTRACER_LAF} picks another:
 * {@code flatlaf}, {@code flatlaf-dark}, {@code system} (the platform's) or {@code metal} (Swing's
 * default). A look and feel that cannot be set leaves Swing's default, which always works.
 */
final class LookAndFeels {

    private LookAndFeels() {
    }

    static String chosen() {
        String p = System.getProperty("raytracer.laf");
        if (p == null || p.isBlank()) {
            p = System.getenv("RAYTRACER_LAF");
        }
        return p == null || p.isBlank() ? "flatlaf" : p.trim().toLowerCase(Locale.ROOT);
    }

    /** Installs the chosen look and feel (on the event thread, before the first window). */
    static void install() {
        String name = chosen();
        try {
            switch (name) {
                case "flatlaf-dark", "dark" -> FlatDarkLaf.setup();
                case "system" -> UIManager.setLookAndFeel(UIManager.getSystemLookAndFeelClassName());
                case "metal", "default", "swing" -> UIManager.setLookAndFeel(UIManager.getCrossPlatformLookAndFeelClassName());
                default -> {
                    if (!"flatlaf".equals(name) && !"flatlaf-light".equals(name) && !"light".equals(name)) {
                        System.err.println("raytracer: unknown look and feel '" + name
                                + "' (expected flatlaf, flatlaf-dark, system or metal); using flatlaf");
                    }
                    FlatLightLaf.setup();
                }
            }
        } catch (ReflectiveOperationException | UnsupportedLookAndFeelException | RuntimeException e) {
            System.err.println("raytracer: cannot use the look and feel '" + name + "' (" + e + "); using Swing's default");
        }
    }
}
