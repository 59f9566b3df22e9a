using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.Simulator.Tests.Reference.V3;

/// <summary>The reference model's defaults are those of a handler generated with the defaults (9600 8N1).</summary>
public sealed class HandlerSetupTests
{
    [Fact]
    public void DefaultEndTimeout_IsTheGeneratorsAt9600Baud8N1()
    {
        var setup = new HandlerSetup(new Station(2), CpuProfiles.For(CpuModel.Cpu224));

        setup.EndTimeoutMs.Should().Be(4).And.Be((byte)V3LinkOptions.DefaultEndTimeoutMs(9600, Parity.None, 8));
    }
}
