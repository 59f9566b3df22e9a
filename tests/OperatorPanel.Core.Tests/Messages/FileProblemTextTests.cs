using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Tests.Messages;

public sealed class FileProblemTextTests
{
    [Fact]
    public void Describe_AccessDeniedOnAFile_SaysTheUserMayNotAndNotTheRuntimeSentence()
    {
        var path = Path.Combine(Path.GetTempPath(), "no-folder-" + Guid.NewGuid().ToString("N"), "line.opproj");

        FileProblemText.Describe(new UnauthorizedAccessException($"Access to the path '{path}' is denied."), path, FileAction.Read)
            .Should().Be("access denied: the user running the panel may not read it");
    }

    [Fact]
    public void Describe_SharingViolation_SaysAnotherProgramHoldsIt()
    {
        FileProblemText.Describe(new IOException("The process cannot access the file because it is being used by another process.", unchecked((int)0x80070020)), "x", FileAction.Write)
            .Should().Be("another program has it open and locked; close that program and try again");
    }

    [Fact]
    public void Describe_UnknownSystemError_IsFramedAsTheSystemsReport()
    {
        FileProblemText.Describe(new IOException("Input/output error", 5), "x", FileAction.Read)
            .Should().Be("the system could not read it (Input/output error)");
    }
}
