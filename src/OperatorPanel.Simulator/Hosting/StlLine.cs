using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// STL stations (<see cref="StlStation"/>) on one <see cref="FreeportBus"/>: what the PC sends reaches every port at the
/// line's baud rate, each CPU executes its .awl in simulated time, and the characters its port sends come back with
/// the time they finished. Stations and demo processes advance in step, at most <see cref="Slice"/> at a time, so one
/// station's reply reaches the others (RS-485) before they run past it.
/// </summary>
public sealed class StlLine : ISimulatedLine
{
    /// <summary>About one character at 9600 baud: finer than any receive timer the handler sets.</summary>
    public static readonly TimeSpan Slice = TimeSpan.FromMilliseconds(1);

    private readonly List<StlStation> _stations = [];
    private readonly List<DemoProcess> _processes = [];

    public StlLine(LineSettings pcLine) => Bus = new FreeportBus(pcLine);

    public FreeportBus Bus { get; }

    public IReadOnlyList<StlStation> Stations => _stations;

    public IReadOnlyList<DemoProcess> Processes => _processes;

    public TimeSpan Now { get; private set; }

    public int FramesReceived { get; private set; }

    public int Replies { get; private set; }

    /// <summary>PPI telegrams the stations' PPI sides answered (acknowledges, data and repeats).</summary>
    public int PpiFramesAnswered => _stations.Sum(s => s.Ppi?.FramesAnswered ?? 0);

    public TimeSpan? NextOutput => null;

    /// <summary>Puts <paramref name="station"/> on the bus; with <paramref name="runProcess"/> the demo bottle filler drives its memory.</summary>
    public void Attach(StlStation station, bool runProcess)
    {
        ArgumentNullException.ThrowIfNull(station);
        Bus.Attach(station.Port);
        _stations.Add(station);
        if (runProcess)
        {
            _processes.Add(new DemoProcess(station));
        }
    }

    public void RunUntil(TimeSpan until)
    {
        while (Now < until)
        {
            var step = Now + Slice < until ? Now + Slice : until;
            foreach (var process in _processes)
            {
                process.Advance(step - Now);
            }

            foreach (var station in _stations)
            {
                station.RunUntil(step);
            }

            Now = step;
        }
    }

    public void Deliver(ReadOnlySpan<byte> characters)
    {
        foreach (var b in characters)
        {
            FramesReceived += b == FrameCodec.EndChar ? 1 : 0;
        }

        Bus.Deliver(characters, Now);
    }

    public byte[] TakeTransmitted() => [.. TakeCharacters().Select(c => c.Value)];

    /// <summary>Like <see cref="TakeTransmitted"/>, with the time each character finished on the wire (for timing tests).</summary>
    public IReadOnlyList<WireCharacter> TakeCharacters()
    {
        var sent = Bus.TakeTransmitted().Where(c => !c.IsBreak).ToList();
        Replies += sent.Count(c => c.Value == FrameCodec.EndChar && !c.IsPpi);
        return sent;
    }
}
