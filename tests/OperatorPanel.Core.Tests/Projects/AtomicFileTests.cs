using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class AtomicFileTests
{
    [Fact]
    public void TryReadAll_FileOverTheLimit_StopsReadingAndSaysSo()
    {
        using var folder = new TempFolder();
        var path = folder.File("big.opproj");
        File.WriteAllBytes(path, new byte[100]);

        AtomicFile.TryReadAll(path, maxBytes: 10, out var bytes, out var error).Should().BeFalse();

        bytes.Should().BeNull();
        error.Should().Be("the file is larger than 10 bytes, the most this kind of file may have");
    }
}
