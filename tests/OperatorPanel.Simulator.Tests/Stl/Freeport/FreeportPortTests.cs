using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Stl.Freeport;

/// <summary>XMT, event numbers per port, PPI/STOP behaviour and half duplex.</summary>
public sealed class FreeportPortTests
{
    [Fact]
    public void Transmit_TenCharactersAt9600_CompletesAfter10Point4167MsWithEvent9()
    {
        var rig = new PortRig().Setup();
        rig.RunTo(PortRig.Ms(2));
        rig.LoadTransmitBuffer("<0123456>\r");

        rig.Port.Transmit(PortRig.Buffer);
        (rig.Memory.SM[4] & 0x20).Should().Be(0, "SM4.5 is off while the transmitter is busy");
        rig.RunToEnd();

        var sent = rig.Port.TakeTransmitted();
        sent.Select(c => (char)c.Value).Should().Equal("<0123456>\r");
        sent[0].At.Should().Be(PortRig.Ms(2) + TimeSpan.FromTicks(10_417));
        sent[^1].At.Should().Be(PortRig.Ms(2) + TimeSpan.FromTicks(104_167), "10 x 10 bits / 9600 baud = 10.4167 ms");
        rig.Events.Should().Equal(new StlEvent(9, sent[^1].At));
        (rig.Memory.SM[4] & 0x20).Should().Be(0x20);
        rig.Port.TakeTransmitted().Should().BeEmpty();
    }

    [Fact]
    public void Transmit_CountZero_SendsBreakOf16BitTimes()
    {
        var rig = new PortRig().Setup();
        rig.Memory.V[PortRig.Buffer] = 0;

        rig.Port.Transmit(PortRig.Buffer);
        rig.RunToEnd();

        rig.Port.TakeTransmitted().Should().Equal(new WireCharacter(0, TimeSpan.FromTicks(16_667), IsBreak: true));
        rig.Events.Should().Equal(new StlEvent(9, TimeSpan.FromTicks(16_667)));
    }

    [Fact]
    public void Port1_ReceiveAndTransmit_UseSmb130Smb186AndEvents25_24_26AndSm46()
    {
        var rig = new PortRig(CpuModel.Cpu226, port: 1).Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<1>", TimeSpan.Zero);
        rig.RunToEnd();
        rig.LoadTransmitBuffer("OK");
        rig.Port.Transmit(PortRig.Buffer);
        (rig.Memory.SM[4] & 0x40).Should().Be(0);
        rig.RunToEnd();

        rig.Events.Select(e => e.Number).Should().Equal(25, 25, 25, 24, 26);
        rig.Memory.SM[186].Should().Be(0x20);
        rig.Memory.SM[86].Should().Be(0);
        (rig.Memory.SM[4] & 0x40).Should().Be(0x40);
    }

    [Fact]
    public void Constructor_Port1OnCpu224_Throws()
    {
        var act = () => new PortRig(CpuModel.Cpu224, port: 1);

        act.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Receive_InPpiMode_DoesNothingAndCharactersAreLost()
    {
        var rig = new PortRig().Setup(mode: 0x08);
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<1>", TimeSpan.Zero);

        rig.RunToEnd();

        rig.Port.IsFreeport.Should().BeFalse();
        rig.Port.LastFault.Should().Be(FreeportFault.NotFreeport);
        rig.Port.LostCharacters.Should().Be(3);
        rig.Events.Should().BeEmpty();
        rig.Status.Should().Be(0);
    }

    [Fact]
    public void Transmit_InPpiMode_SendsNothing()
    {
        var rig = new PortRig().Setup(mode: 0x00);
        rig.LoadTransmitBuffer("OK");

        rig.Port.Transmit(PortRig.Buffer);
        rig.RunToEnd();

        rig.Port.TakeTransmitted().Should().BeEmpty();
        rig.Port.LastFault.Should().Be(FreeportFault.NotFreeport);
        rig.Port.NextChange.Should().BeNull();
    }

    [Fact]
    public void Reset_CpuLeavesRunDuringReceive_EndsItSilentlyAndReturnsToPpi()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<01", TimeSpan.Zero);
        rig.RunTo(PortRig.Ms(10));

        rig.Port.Reset();
        rig.Deliver("2>", PortRig.Ms(10));
        rig.RunToEnd();

        rig.Port.IsFreeport.Should().BeFalse();
        rig.Events.Should().NotContain(e => e.Number == 23);
        rig.Port.LostCharacters.Should().Be(2);
    }

    [Fact]
    public void AdvanceTo_ModeBitsRewrittenToPpi_StopsTransmissionAfterTheCurrentCharacter()
    {
        var rig = new PortRig().Setup();
        rig.LoadTransmitBuffer("ABCDEF");
        rig.Port.Transmit(PortRig.Buffer);
        rig.RunTo(PortRig.Ms(1.5));

        rig.Memory.SM[30] = 0x00;
        rig.RunToEnd();

        rig.Port.TakeTransmitted().Select(c => (char)c.Value).Should().Equal('A');
        rig.Events.Should().BeEmpty();
        (rig.Memory.SM[4] & 0x20).Should().Be(0x20);
    }

    [Fact]
    public void Transmit_WhileReceiveActive_IsRefusedAndTheReceiveCarriesOn()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.LoadTransmitBuffer("OK");

        rig.Port.Transmit(PortRig.Buffer);
        rig.Port.LastFault.Should().Be(FreeportFault.SimultaneousTransmitReceive);
        rig.Deliver("<1>", TimeSpan.Zero);
        rig.RunToEnd();

        rig.Port.TakeTransmitted().Should().BeEmpty();
        rig.Status.Should().Be(0x20);
    }

    [Fact]
    public void Receive_WhileTransmitting_IsRefused()
    {
        var rig = new PortRig().Setup();
        rig.LoadTransmitBuffer("OK");
        rig.Port.Transmit(PortRig.Buffer);

        rig.Port.Receive(PortRig.Buffer + 10);

        rig.Port.LastFault.Should().Be(FreeportFault.SimultaneousTransmitReceive);
        rig.Port.IsReceiving.Should().BeFalse();
    }

    [Fact]
    public void Receive_PcWithoutParityPortEven_StartCharacterFailsParityAndNothingIsReceived()
    {
        var rig = new PortRig(pc: LineSettings.Default).Setup(mode: 0x49);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("<0102030405060708>", TimeSpan.Zero);
        rig.RunToEnd();

        rig.Port.Line.Should().Be(new LineSettings(9600, Parity.Even, 8));
        rig.Port.IsReceiving.Should().BeTrue();
        rig.Memory.V[PortRig.Buffer].Should().Be(0);
        (rig.Memory.SM[3] & 1).Should().Be(1, "the PC's stop bit is read as the parity bit, so characters arrive with parity or framing errors");
    }

    [Fact]
    public void Receive_AnyCharacterWithParityError_EndsTheMessageWithStatusP()
    {
        var rig = new PortRig(pc: LineSettings.Default).Setup(mode: 0x49, control: 0xB0, idleMs: 0);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("<01>", TimeSpan.Zero);
        rig.RunToEnd();

        rig.Status.Should().Be(0x01);
        rig.Events.Last(e => e.Number == 23).At.Should().Be(new LineSettings(9600, Parity.Even, 8).CharacterTime);
    }

    [Theory]
    [InlineData(19200, Parity.None, 8)]
    [InlineData(4800, Parity.None, 8)]
    [InlineData(9600, Parity.None, 7)]
    [InlineData(9600, Parity.Odd, 8)]
    public void Receive_PcWithOtherSettings_NeverDeliversTheFrame(int baud, Parity parity, int dataBits)
    {
        var rig = new PortRig(pc: new LineSettings(baud, parity, dataBits)).Setup(control: 0xE4, timerMs: 50);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("<0102030405060708>", TimeSpan.Zero);
        rig.RunTo(PortRig.Ms(500));

        (rig.Port.IsReceiving && rig.Status == 0x20).Should().BeFalse();
        rig.ReceivedText.Should().NotBe("<0102030405060708>");
    }
}
