using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>What a failure tells the technician to check: on a PPI bus the CPU's port and the bus, never the handler.</summary>
public sealed class LinkFailureTests
{
    private static LinkTarget Target(LinkProtocol protocol) => new(
        new Station(2),
        new SerialSettings { PortName = "COM3", BaudRate = 9600, Parity = Parity.Even, Protocol = protocol },
        null,
        Demo: false,
        TimeSpan.FromMilliseconds(100));

    [Theory]
    [InlineData(PlcErrorKind.NoAnswer, "nothing answers at PPI address 2: check the CPU's port settings in its system block (PPI address 2, 9600 baud")]
    [InlineData(PlcErrorKind.Timeout, "the CPU at PPI address 2 took the job but its answer did not come within the time allowed")]
    [InlineData(PlcErrorKind.FrameCorrupt, "the answers were garbled or not the answer to this job: check that the CPU's port runs PPI at 9600 baud")]
    public void HintFor_PpiFailure_NamesThePpiChecksNotTheHandlers(PlcErrorKind kind, string start)
    {
        var hint = LinkFailure.HintFor(Target(LinkProtocol.Ppi), kind);

        hint.Should().StartWith(start);
        hint.Should().NotContainAny("handler", "OP_PANEL", "OB1", "8E1");
    }

    [Fact]
    public void HintFor_PpiReferenceMismatch_SaysItIsALateAnswer()
    {
        var hint = LinkFailure.HintFor(Target(LinkProtocol.Ppi), PlcErrorKind.FrameCorrupt);

        hint.Should().Contain("a ReferenceMismatch is a late answer to an earlier job");
    }

    [Fact]
    public void HintFor_FreeportGarbled_StillNamesTheHandlersSetting()
    {
        var hint = LinkFailure.HintFor(Target(LinkProtocol.Freeport), PlcErrorKind.FrameCorrupt);

        hint.Should().StartWith("replies arrive garbled: check that 9600 8E1 is the handler's setting");
    }

    [Fact]
    public void HintFor_PpiPortUnavailable_SameAsFreeport()
    {
        LinkFailure.HintFor(Target(LinkProtocol.Ppi), PlcErrorKind.PortUnavailable)
            .Should().Be(LinkFailure.HintFor(Target(LinkProtocol.Freeport), PlcErrorKind.PortUnavailable));
    }
}
