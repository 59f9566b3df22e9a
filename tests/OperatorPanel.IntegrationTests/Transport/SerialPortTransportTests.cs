using System.Diagnostics;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.IntegrationTests.Transport;

/// <summary>
/// The OS serial transport on real pseudo-terminals. These use real time (they are device tests), bounded so each
/// finishes well under 5 s.
/// </summary>
public sealed class SerialPortTransportTests
{
    private static readonly TimeSpan ReadTimeout = TimeSpan.FromMilliseconds(300);

    [Theory]
    [InlineData(9600, 8, Parity.None)]
    [InlineData(115200, 8, Parity.None)]
    [InlineData(9600, 7, Parity.Even)]
    [InlineData(115200, 7, Parity.Even)]
    public async Task WriteRead_BothWays_ExactBytesArrive(int baud, int dataBits, Parity parity)
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA, baud, dataBits, parity);
        await using var plc = await OpenAsync(pty.PathB, baud, dataBits, parity);

        await panel.WriteAsync(Hex.Ascii("<0101017E>"), default);
        (await ReadExactlyAsync(plc, 10)).Should().Equal(Hex.Ascii("<0101017E>"));

        await plc.WriteAsync(Hex.Ascii("<01018100>"), default);
        (await ReadExactlyAsync(panel, 10)).Should().Equal(Hex.Ascii("<01018100>"));
    }

    [Fact]
    public async Task Read_NothingSent_ReturnsZeroAfterTheTimeout()
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA);
        var watch = Stopwatch.StartNew();

        var count = await panel.ReadAsync(new byte[16], ReadTimeout, default);

        count.Should().Be(0);
        watch.Elapsed.Should().BeGreaterThan(ReadTimeout * 0.8).And.BeLessThan(TimeSpan.FromSeconds(3));
    }

    [Fact]
    public async Task Write_LongestFrame_ArrivesComplete()
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA, 115200);
        await using var plc = await OpenAsync(pty.PathB, 115200);
        var frame = Hex.Ascii("<" + string.Concat(Enumerable.Range(0, 253).Select(i => "0123456789ABCDEF"[i % 16])) + ">");

        await panel.WriteAsync(frame, default);

        frame.Should().HaveCount(255);
        (await ReadExactlyAsync(plc, 255)).Should().Equal(frame);
    }

    [Fact]
    public async Task DiscardInput_OpenPort_NextExchangeArrivesIntact()
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA);
        await using var plc = await OpenAsync(pty.PathB);

        panel.DiscardInput();
        await plc.WriteAsync(Hex.Ascii("<new>"), default);

        (await ReadExactlyAsync(panel, 5)).Should().Equal(Hex.Ascii("<new>"));
    }

    [Fact]
    public async Task Open_PortAlreadyOpenHere_IsRefusedAndFreeAgainAfterClose()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var first = await OpenAsync(pty.PathA);
        await using var second = new SerialPortTransport(new SerialSettings { PortName = pty.PathA });

        var failure = await second.Invoking(t => t.OpenAsync(default)).Should().ThrowAsync<PlcCommunicationException>();
        failure.Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
        failure.Which.Message.Should().Be($"serial port {pty.PathA} is already open in this program");

        await first.DisposeAsync();
        await using var third = await OpenAsync(pty.PathA);
        third.IsOpen.Should().BeTrue();
    }

    [Fact]
    public async Task Open_PortLockedByAnotherRunningProgram_IsRefusedNamingIt()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var lockFile = PortLock.PathFor(pty.PathA, PortLock.DefaultFolder);
        File.WriteAllText(lockFile, "         1\n");
        try
        {
            await using var transport = new SerialPortTransport(new SerialSettings { PortName = pty.PathA });

            var failure = await transport.Invoking(t => t.OpenAsync(default)).Should().ThrowAsync<PlcCommunicationException>();

            failure.Which.Message.Should().StartWith($"serial port {pty.PathA} is in use by another program: ").And.Contain("(PID 1)");
            File.Exists(lockFile).Should().BeTrue("the other program's lock stays");
        }
        finally
        {
            File.Delete(lockFile);
        }
    }

    [Fact]
    public async Task Open_MissingDevice_FailsWithPortUnavailableNamingThePath()
    {
        var path = Path.Combine(Path.GetTempPath(), "opanel-missing-" + Guid.NewGuid().ToString("N"));
        await using var transport = new SerialPortTransport(new SerialSettings { PortName = path });

        var failure = await transport.Invoking(t => t.OpenAsync(default)).Should().ThrowAsync<PlcCommunicationException>();

        failure.Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
        failure.Which.Message.Should().Contain(path).And.Contain("ENOENT");
        transport.IsOpen.Should().BeFalse();
    }

    [Fact]
    public async Task Open_RegularFile_FailsWithPortUnavailable()
    {
        var path = Path.GetTempFileName();
        try
        {
            await using var transport = new SerialPortTransport(new SerialSettings { PortName = path });

            var failure = await transport.Invoking(t => t.OpenAsync(default)).Should().ThrowAsync<PlcCommunicationException>();

            failure.Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
            failure.Which.Message.Should().Contain(path).And.Contain("ENOTTY");
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public async Task Read_DeviceVanishes_FailsWithPortUnavailableInsteadOfHanging()
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA);
        var pending = panel.ReadAsync(new byte[16], TimeSpan.FromSeconds(3), default);

        pty.Kill();

        var failure = await pending.Invoking(p => p).Should().ThrowAsync<PlcCommunicationException>();
        failure.Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
        failure.Which.Message.Should().Contain(pty.PathA);
    }

    [Fact]
    public async Task Write_DeviceVanished_FailsWithPortUnavailable()
    {
        using var pty = await SocatPtyPair.StartAsync();
        await using var panel = await OpenAsync(pty.PathA);

        pty.Kill();

        (await panel.Invoking(p => p.WriteAsync(Hex.Ascii("<01>"), default)).Should().ThrowAsync<PlcCommunicationException>())
            .Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
    }

    [Fact]
    public async Task Read_AfterDispose_FailsWithPortUnavailable()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var panel = await OpenAsync(pty.PathA);
        await panel.DisposeAsync();

        (await panel.Invoking(p => p.ReadAsync(new byte[1], ReadTimeout, default)).Should().ThrowAsync<PlcCommunicationException>())
            .Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
    }

    private static async Task<SerialPortTransport> OpenAsync(string path, int baud = 9600, int dataBits = 8, Parity parity = Parity.None)
    {
        var transport = new SerialPortTransport(new SerialSettings
        {
            PortName = path,
            BaudRate = baud,
            DataBits = dataBits,
            Parity = parity,
        });
        await transport.OpenAsync(default);
        transport.IsOpen.Should().BeTrue();
        return transport;
    }

    /// <summary>Reads until <paramref name="count"/> bytes came; a pty may deliver a frame in pieces.</summary>
    private static async Task<byte[]> ReadExactlyAsync(SerialPortTransport transport, int count)
    {
        var buffer = new byte[count + 16];
        var total = 0;
        while (total < count)
        {
            var read = await transport.ReadAsync(buffer.AsMemory(total), ReadTimeout, default);
            if (read == 0)
            {
                break;
            }

            total += read;
        }

        return buffer[..total];
    }
}
