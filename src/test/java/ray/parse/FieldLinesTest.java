package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The parser's record of which fields the current object has set, and where: the first line wins. */
class FieldLinesTest {

    @Test
    void firstLineIsKeptAndReportedForEveryFieldBeyondTheInitialCapacity() {
        FieldLines f = new FieldLines();
        for (int i = 0; i < 20; i++) {
            assertEquals(-1, f.putIfAbsent(new String("field" + i), 100 + i));   // equal names, not the same strings
        }
        for (int i = 0; i < 20; i++) {
            assertTrue(f.contains("field" + i));
            assertEquals(100 + i, f.putIfAbsent("field" + i, 999), "field" + i);
        }
        assertFalse(f.contains("field20"));
        f.clear();
        assertFalse(f.contains("field0"));
        assertEquals(-1, f.putIfAbsent("field0", 7));
        assertEquals(7, f.putIfAbsent("field0", 8));
    }
}
