package ray.parse;

import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;

/** For tests outside this package: an object that {@code init()} refuses is one located line. */
public final class ObjectErrors {

    private ObjectErrors() {
    }

    /**
     * Parses a scene whose line 6 is {@code header} followed by the parameter line {@code line}, and
     * checks the one-line message {@code bad.txt:6: <header>: ...} contains {@code expected}.
     */
    public static void assertRefused(String header, String line, String expected) {
        String text = "Width 1\nHeight 1\n\nCamera Camera\n\n" + header + "\n" + line + "\n";
        SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(text, "bad.txt", new ArrayList<>()));
        ParserTest.assertLocated(e, "bad.txt", 6, header + ": ", expected);
    }
}
