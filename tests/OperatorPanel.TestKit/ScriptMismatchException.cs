namespace OperatorPanel.TestKit;

/// <summary>The code under test did not follow the script of a <see cref="ScriptedTransport"/>: the test fails.</summary>
public sealed class ScriptMismatchException : Exception
{
    public ScriptMismatchException()
    {
    }

    public ScriptMismatchException(string message)
        : base(message)
    {
    }

    public ScriptMismatchException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
