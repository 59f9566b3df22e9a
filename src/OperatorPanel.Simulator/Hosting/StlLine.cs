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
    private readonly Core.Protocol.V3.Reader _requests = new(Core.Protocol.V3.Codec.MinRequestLen);
    private readonly Core.Protocol.V3.Reader _replies = new();

    public StlLine(LineSettings pcLine) => Bus = new FreeportBus(pcLine);

    public FreeportBus Bus { get; }

    public IReadOnlyList<StlStation> Stations => _stations;

    public IReadOnlyList<DemoProcess> Processes => _processes;

    public TimeSpan Now { get; private set; }

    /// <summary>
    /// The protocol the handlers speak, for counting frames (<see cref="FramesReceived"/>, <see cref="Replies"/>): 2 ends
    /// a frame at '&gt;'; 3 (binary frames) cuts them by LEN as a radio module does (Protocol/V3's Reader).
    /// </summary>
    public int Protocol { get; init; } = 2;

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
        FramesReceived += Protocol == 3 ? Count(_requests, characters) : characters.Count(FrameCodec.EndChar);

        Bus.Deliver(characters, Now);
    }

    public byte[] TakeTransmitted() => [.. TakeCharacters().Select(c => c.Value)];

    /// <summary>Like <see cref="TakeTransmitted"/>, with the time each character finished on the wire (for timing tests).</summary>
    public IReadOnlyList<WireCharacter> TakeCharacters()
    {
        var sent = Bus.TakeTransmitted().Where(c => !c.IsBreak).ToList();
        byte[] freeport = [.. sent.Where(c => !c.IsPpi).Select(c => c.Value)];
        Replies += Protocol == 3 ? Count(_replies, freeport) : freeport.Count(b => b == FrameCodec.EndChar);
        return sent;
    }

    private static int Count(Core.Protocol.V3.Reader reader, ReadOnlySpan<byte> bytes)
    {
        reader.Append(bytes);
        var frames = 0;
        while (reader.TryTake(out _))
        {
            frames++;
        }

        return frames;
    }
}
