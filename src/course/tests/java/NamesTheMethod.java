import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.TestExecutionExceptionHandler;
import org.opentest4j.AssertionFailedError;
import org.opentest4j.TestAbortedException;

/**
 * When your method throws (a NullPointerException, a StackOverflowError ...), the test fails with a message
 * that starts with the method's name and says where it threw; the exception itself stays attached, with
 * its stack trace.
 */
public class NamesTheMethod implements TestExecutionExceptionHandler {

    @Override
    public void handleTestExecutionException(ExtensionContext context, Throwable thrown) throws Throwable {
        if (thrown instanceof AssertionError || thrown instanceof TestAbortedException) {
            throw thrown;
        }
        Tag tag = context.getRequiredTestClass().getAnnotation(Tag.class);
        String method = tag != null && tag.value().startsWith("method:") ? tag.value().substring("method:".length()) : "your code";
        String at = "";
        for (StackTraceElement f : thrown.getStackTrace()) {
            String c = f.getClassName();
            if (!c.contains(".") && !c.endsWith("Test") && !c.startsWith("Doubles") && !c.startsWith("Expect")) {
                at = " at " + f;
                break;
            }
        }
        String message = thrown.getMessage() == null ? "" : " (" + thrown.getMessage() + ")";
        if (thrown instanceof StackOverflowError) {
            message = " (a method that calls itself without end)";
        }
        throw new AssertionFailedError(method + " threw " + thrown.getClass().getSimpleName() + message + at, thrown);
    }
}
