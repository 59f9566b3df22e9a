using System.Text;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Stl.Freeport;

public sealed class FreeportBusTests
{
    [Fact]
    public void Deliver_FromPc_ReachesEveryStation()
    {
        var (bus, a, b) = TwoStations();
        a.Port.Receive(PortRig.Buffer);
        b.Port.Receive(PortRig.Buffer);

        bus.Deliver("<02>"u8, PortRig.Ms(1));
        RunAll(bus, a, b);

        a.ReceivedText.Should().Be("<02>");
        b.ReceivedText.Should().Be("<02>");
        a.Events.Last().Should().Be(new StlEvent(23, PortRig.Ms(1) + PortRig.Chars(4)));
        b.Events.Last().Should().Be(a.Events.Last());
    }

    [Fact]
    public void Transmit_FromOneStation_ReachesThePcAndTheOtherStationButNotItself()
    {
        var (bus, a, b) = TwoStations();
        b.Port.Receive(PortRig.Buffer);
        a.LoadTransmitBuffer("<R1>");

        a.Port.Transmit(PortRig.Buffer);
        RunAll(bus, a, b);

        var heard = bus.TakeTransmitted();
        Encoding.ASCII.GetString(heard.Select(c => c.Value).ToArray()).Should().Be("<R1>");
        heard[^1].At.Should().Be(PortRig.Chars(4));
        b.ReceivedText.Should().Be("<R1>");
        a.Port.LostCharacters.Should().Be(0);
    }

    [Fact]
    public void Transmit_TwoStationsAtOnce_CollideAndTheListenerGetsNoFrame()
    {
        var (bus, a, b) = TwoStations();
        var listener = new PortRig().Setup();
        bus.Attach(listener.Port);
        listener.Port.Receive(PortRig.Buffer);
        a.LoadTransmitBuffer("<AAAA>");
        b.LoadTransmitBuffer("<5555>");

        a.Port.Transmit(PortRig.Buffer);
        b.Port.Transmit(PortRig.Buffer);
        RunAll(bus, a, b, listener);

        listener.ReceivedText.Should().NotBe("<AAAA>").And.NotBe("<5555>");
    }

    [Fact]
    public void Attach_PortAlreadyOnABus_Throws()
    {
        var (bus, a, _) = TwoStations();

        var act = () => bus.Attach(a.Port);

        act.Should().Throw<InvalidOperationException>();
    }

    private static (FreeportBus Bus, PortRig A, PortRig B) TwoStations()
    {
        var bus = new FreeportBus(LineSettings.Default);
        var a = new PortRig().Setup();
        var b = new PortRig().Setup();
        bus.Attach(a.Port);
        bus.Attach(b.Port);
        return (bus, a, b);
    }

    /// <summary>Advances every station in step to the bus's next change, as a host running several PLCs does.</summary>
    private static void RunAll(FreeportBus bus, params PortRig[] stations)
    {
        for (var guard = 0; guard < 10_000 && bus.NextChange is { } next; guard++)
        {
            foreach (var station in stations)
            {
                station.RunTo(next);
            }
        }
    }
}
