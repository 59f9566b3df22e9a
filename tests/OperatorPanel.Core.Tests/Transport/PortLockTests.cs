using System.Diagnostics;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Transport;

/// <summary>The UUCP-style port lock (FHS 3.0 section 5.9): one program per port, stale locks of dead programs taken over.</summary>
public sealed class PortLockTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-locks-" + Guid.NewGuid().ToString("N"));
    private readonly string _port = "/dev/ttyTEST" + Random.Shared.Next(1000, 9999);

    public void Dispose()
    {
        if (Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
    }

    [Fact]
    public void TryAcquire_FreePort_WritesOurPidAsTenDigitsAndANewline()
    {
        PortLock.TryAcquire(_port, _folder, out var held, out var error).Should().BeTrue(error);
        using (held)
        {
            var path = Path.Combine(_folder, "LCK.." + Path.GetFileName(_port));
            File.ReadAllText(path).Should().Be(Environment.ProcessId.ToString(System.Globalization.CultureInfo.InvariantCulture).PadLeft(10) + "\n");
        }

        Directory.GetFiles(_folder).Should().BeEmpty("releasing the port removes its lock");
    }

    [Fact]
    public void TryAcquire_PortHeldByARunningProgram_RefusesNamingThePortAndTheProgram()
    {
        Directory.CreateDirectory(_folder);
        File.WriteAllText(PortLock.PathFor(_port, _folder), "         1\n"); // PID 1 always runs

        PortLock.TryAcquire(_port, _folder, out var held, out var error).Should().BeFalse();

        held.Should().BeNull();
        error.Should().StartWith($"serial port {_port} is in use by another program: ").And.EndWith(" (PID 1); close it first, one program per port");
    }

    [Fact]
    public void TryAcquire_LockOfAProgramThatEnded_IsTakenOver()
    {
        Directory.CreateDirectory(_folder);
        using var ended = Process.Start(new ProcessStartInfo("true") { UseShellExecute = false })!;
        ended.WaitForExit();
        File.WriteAllText(PortLock.PathFor(_port, _folder), $"{ended.Id,10}\n");

        PortLock.TryAcquire(_port, _folder, out var held, out var error).Should().BeTrue(error);

        using (held)
        {
            File.ReadAllText(PortLock.PathFor(_port, _folder)).Trim().Should().Be(Environment.ProcessId.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
    }

    [Fact]
    public void TryAcquire_SamePortTwiceInOneProgram_RefusesTheSecondUntilTheFirstIsReleased()
    {
        PortLock.TryAcquire(_port, _folder, out var first, out _).Should().BeTrue();

        PortLock.TryAcquire(_port, _folder, out _, out var error).Should().BeFalse();
        error.Should().Be($"serial port {_port} is already open in this program");

        first!.Dispose();
        PortLock.TryAcquire(_port, _folder, out var again, out _).Should().BeTrue();
        again!.Dispose();
    }

    [Theory]
    [InlineData("COM3", "LCK..COM3")]
    [InlineData("/dev/ttyUSB0", "LCK..ttyUSB0")]
    [InlineData("/dev/pts/4", "LCK..pts_4")]
    public void PathFor_DeviceName_FollowsTheUucpNaming(string port, string file)
    {
        Path.GetFileName(PortLock.PathFor(port, _folder)).Should().Be(file);
    }
}
