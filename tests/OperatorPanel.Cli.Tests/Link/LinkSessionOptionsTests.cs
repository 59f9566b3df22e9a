using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Tests.Link;

/// <summary>What --scan-ms does to the protocol 3 link's reply time-out (docs/protocol.md section 7).</summary>
public sealed class LinkSessionOptionsTests
{
    private static readonly SerialSettings Line = new() { PortName = "COM3", BaudRate = 9600 };

    [Fact]
    public void OptionsFor_DefaultScan_OnlyTheScanBeforeTheHandlerStarts()
    {
        var options = LinkSession.OptionsFor(Line, TimeSpan.FromMilliseconds(100), demo: false);

        options.ScanAllowance.Should().Be(TimeSpan.FromMilliseconds(100));
        options.HandlerScanAllowance.Should().Be(TimeSpan.FromMilliseconds(30));
    }

    [Fact]
    public void OptionsFor_ScanRaisedForALongProgram_EveryScanOfTheHandlerAllowedThatLong()
    {
        var options = LinkSession.OptionsFor(Line, TimeSpan.FromMilliseconds(400), demo: false);

        options.ScanAllowance.Should().Be(TimeSpan.FromMilliseconds(400));
        options.HandlerScanAllowance.Should().Be(TimeSpan.FromMilliseconds(400));
    }
}
