using System.Collections.ObjectModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>
/// Builds the byte groups of the Inputs or Outputs window; each lamp subscribes to its own address on the session's
/// line, so a value change goes to that lamp and no other.
/// </summary>
internal sealed class IoPointMap<T>(PanelSession session, Func<ProjectStation, IEnumerable<IoSymbol>> symbolsOf, Func<ProjectStation, IoSymbol, T> create)
    where T : IoPointViewModel
{
    private readonly List<T> _points = [];
    private readonly List<IDisposable> _subscriptions = [];

    public ObservableCollection<IoByteGroup<T>> Groups { get; } = [];

    public IEnumerable<T> Points => _points;

    public void Rebuild()
    {
        _subscriptions.ForEach(s => s.Dispose());
        _subscriptions.Clear();
        _points.Clear();
        Groups.Clear();
        foreach (var station in session.Project.Stations)
        {
            foreach (var bytes in symbolsOf(station).GroupBy(s => s.Address.ByteOffset).OrderBy(g => g.Key))
            {
                var points = bytes.OrderBy(s => s.Address.Bit).Select(s => create(station, s)).ToList();
                _points.AddRange(points);
                var first = bytes.First().Address;
                Groups.Add(new IoByteGroup<T>(station.Name, PlcAddress.ForBytes(first.Area, first.ByteOffset, AccessWidth.Byte).ToString(), points));
            }
        }

        _subscriptions.AddRange(_points.Select(p => session.Values.Subscribe(p.Station, p.PlcAddress, p.Apply)));
    }
}
