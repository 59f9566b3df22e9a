using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Stl.Freeport;

/// <summary>RCV's receive message function (seed 002, Table C-16) as the port carries it out, in simulated time.</summary>
public sealed class ReceiveMessageTests
{
    [Fact]
    public void Receive_StartAndEndCharacter_StoresFrameWithCountAndRaisesEvent23AtTheLastStopBit()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("x><01>", PortRig.Ms(1));
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("<01>");
        rig.Memory.V[PortRig.Buffer].Should().Be(4);
        rig.Status.Should().Be(0x20);
        rig.Events.Where(e => e.Number == 23).Should().Equal(new StlEvent(23, PortRig.Ms(1) + PortRig.Chars(6)));
        rig.Port.IsReceiving.Should().BeFalse();
        rig.Port.LostCharacters.Should().Be(0);
    }

    [Fact]
    public void Receive_FrameInTwoDeliveries_CharactersFollowBackToBack()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("<01", TimeSpan.Zero);
        rig.RunTo(PortRig.Ms(1));
        rig.Deliver("23>", PortRig.Ms(1));
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("<0123>");
        rig.Events.Last().Should().Be(new StlEvent(23, PortRig.Chars(6)));
    }

    [Fact]
    public void Receive_IdleLineStart_CharactersInsideTheIdleTimeAreDiscarded()
    {
        var rig = new PortRig().Setup(control: 0x90, idleMs: 5, max: 3);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("AB", TimeSpan.Zero);
        rig.Deliver("CD", PortRig.Chars(2) + PortRig.Ms(4));
        rig.Deliver("XYZW", PortRig.Ms(20));
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("XYZ");
        rig.Status.Should().Be(0x02, "SMB94 = 3 characters ends the message with status c");
        rig.Events.Last(e => e.Number == 23).At.Should().Be(PortRig.Ms(20) + PortRig.Chars(3));
        rig.Port.LostCharacters.Should().Be(1, "W arrived after the receive ended");
    }

    [Fact]
    public void Receive_IdleLineZero_RespondsToAnyCharacter()
    {
        var rig = new PortRig().Setup(control: 0xB0, end: (byte)'\r', idleMs: 0);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("OK\r", PortRig.Ms(3));
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("OK\r");
        rig.Status.Should().Be(0x20);
    }

    [Fact]
    public void Receive_InterCharacterTimer_EndsTruncatedFrameWithStatusTAfterTheLastCharacter()
    {
        var rig = new PortRig().Setup(control: 0xE4, timerMs: 100);
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<0123", TimeSpan.Zero);

        var expected = PortRig.Chars(5) + PortRig.Ms(100);
        rig.RunTo(PortRig.Ms(50));
        rig.Port.NextChange.Should().Be(expected);
        rig.RunTo(expected - TimeSpan.FromTicks(1));
        rig.Events.Should().NotContain(e => e.Number == 23);
        rig.RunTo(expected);

        rig.Events.Last().Should().Be(new StlEvent(23, expected));
        rig.Status.Should().Be(0x04);
        rig.ReceivedText.Should().Be("<0123");
    }

    [Fact]
    public void Receive_InterCharacterTimer_DoesNotRunBeforeTheStartCharacter()
    {
        var rig = new PortRig().Setup(control: 0xE4, timerMs: 100);
        rig.Port.Receive(PortRig.Buffer);

        rig.RunTo(PortRig.Ms(500));
        rig.Port.IsReceiving.Should().BeTrue();
        rig.Deliver("<1>", PortRig.Ms(500));
        rig.RunToEnd();

        rig.Status.Should().Be(0x20);
    }

    [Fact]
    public void Receive_MessageTimer_EndsAtStartCharacterPlusTimeoutWhileCharactersStillTrickleIn()
    {
        var rig = new PortRig().Setup(control: 0xEC, timerMs: 19);
        rig.Port.Receive(PortRig.Buffer);
        for (var i = 0; i < 6; i++)
        {
            rig.Deliver(i == 0 ? "<" : "0", PortRig.Ms(5 * i));
        }

        rig.RunToEnd();

        rig.Events.Single(e => e.Number == 23).At.Should().Be(PortRig.Chars(1) + PortRig.Ms(19));
        rig.Status.Should().Be(0x04);
        rig.ReceivedText.Should().Be("<000", "characters from 5, 10 and 15 ms; the one from 20 ms ends after the timer");
    }

    [Fact]
    public void Receive_MessageTimerWithAnyResponse_TimesOutWhenNothingArrives()
    {
        var rig = new PortRig().Setup(control: 0x9C, idleMs: 0, timerMs: 50);
        rig.RunTo(PortRig.Ms(10));
        rig.Port.Receive(PortRig.Buffer);

        rig.RunToEnd();

        rig.Events.Should().Equal(new StlEvent(23, PortRig.Ms(60)));
        rig.Status.Should().Be(0x04);
        rig.Memory.V[PortRig.Buffer].Should().Be(0);
    }

    [Fact]
    public void Receive_MaxCount_EndsWithStatusC()
    {
        var rig = new PortRig().Setup(control: 0xC0, max: 3);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("<ABCD", TimeSpan.Zero);
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("<AB");
        rig.Status.Should().Be(0x02);
    }

    [Fact]
    public void Receive_BreakStart_StoresCharactersAfterTheBreakOnly()
    {
        var rig = new PortRig().Setup(control: 0xA2);
        rig.Port.Receive(PortRig.Buffer);

        rig.Deliver("ZZ>", TimeSpan.Zero);
        rig.Port.DeliverBreak(PortRig.Ms(10));
        rig.Deliver("AB>", PortRig.Ms(20));
        rig.RunToEnd();

        rig.ReceivedText.Should().Be("AB>");
        rig.Status.Should().Be(0x20);
    }

    [Fact]
    public void Receive_EnableBitCleared_EndsActiveReceiveWithStatusNAtThatTime()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<01", TimeSpan.Zero);
        rig.RunTo(PortRig.Ms(10));

        rig.Memory.SM[87] = 0x60;
        rig.Port.Receive(PortRig.Buffer);
        rig.RunTo(PortRig.Ms(10));

        rig.Status.Should().Be(0x80);
        rig.ReceivedText.Should().Be("<01");
        rig.Events.Where(e => e.Number == 23).Should().Equal(new StlEvent(23, PortRig.Ms(10)));
        rig.Port.IsReceiving.Should().BeFalse();
    }

    [Fact]
    public void Receive_NoStartCondition_SetsStatusRAndStartsNothing()
    {
        var rig = new PortRig().Setup(control: 0xA0);

        rig.Port.Receive(PortRig.Buffer);

        rig.Status.Should().Be(0x40);
        rig.Port.IsReceiving.Should().BeFalse();
        rig.Port.LastFault.Should().Be(FreeportFault.ReceiveParameterError);
    }

    [Fact]
    public void Receive_CharactersWhileNoReceiveActive_AreLostAndCounted()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<1><2>", TimeSpan.Zero);

        rig.RunToEnd();

        rig.ReceivedText.Should().Be("<1>");
        rig.Port.LostCharacters.Should().Be(3);
        rig.Events.Count(e => e.Number == 23).Should().Be(1);
    }

    [Fact]
    public void Receive_EachCharacter_RaisesEvent8WithTheCharacterInSmb2()
    {
        var rig = new PortRig().Setup();
        rig.Port.Receive(PortRig.Buffer);
        rig.Deliver("<", TimeSpan.Zero);

        rig.RunToEnd();

        rig.Events.Should().Equal(new StlEvent(8, PortRig.Chars(1)));
        rig.Memory.SM[2].Should().Be((byte)'<');
        (rig.Memory.SM[3] & 1).Should().Be(0);
    }
}
